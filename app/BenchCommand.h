#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold bench ...`: speed against accuracy for every integrator configuration,
// as a table, CSV and a Qt Charts chart (docs/solver-lab.md).
int runBench(const QStringList& arguments);

} // namespace pf::cli
