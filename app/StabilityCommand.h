#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold stability ...`: the solver lab's map of where each method fails.
int runStability(const QStringList& arguments);

} // namespace pf::cli
