#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold figures ...`: the paper's Fig. 10 (φ), Fig. 11 (ψ) and Fig. 12 (σ) as contact
// sheets, one row per parameter value and one column per seed, with the measured counts
// under each picture, and the counts as CSV.
int runFigures(const QStringList& arguments);

} // namespace pf::cli
