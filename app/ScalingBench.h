#pragma once

#include <QString>

namespace pf::cli {

// `paperfold bench --scaling`: the cost of a step per spring against the sheet's size,
// while a tool crumples it (press), while it swings (drape) and while it lies at rest, and
// the largest sheet that runs in real time; a table, scaling.csv and scaling.png.
struct ScalingOptions {
    bool quick = false;
    QString integrator = QStringLiteral("jacobi");
    QString outputDir;
};

int runScalingBench(const ScalingOptions& options);

} // namespace pf::cli
