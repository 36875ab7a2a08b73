#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold fidelity ...`: the scorecard of how much the sheet behaves like paper.
int runFidelity(const QStringList& arguments);

} // namespace pf::cli
