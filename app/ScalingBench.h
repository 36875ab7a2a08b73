#pragma once

#include <QString>

namespace pf::cli {

// `paperfold bench --scaling`: the cost of a step per spring against the sheet's size,
// while a tool crumples it (press), while it swings (drape) and while it lies at rest, and
// the largest sheet that runs in real time, on one thread and on several; a table,
// scaling.csv and scaling.png.
struct ScalingOptions {
    bool quick = false;
    QString integrator = QStringLiteral("jacobi");
    // Each sheet is timed on one thread and, if this is more, on this many.
    int threads = 1;
    QString outputDir;
};

int runScalingBench(const ScalingOptions& options);

} // namespace pf::cli
