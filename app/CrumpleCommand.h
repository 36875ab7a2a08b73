#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold crumple ...`: the crumple-cycles scene measured as experiments measure
// repeatedly crumpled paper: total crease length after each cycle with the fit
// L(n) = a + b ln n, the histogram of crease run lengths (CSV), and the crease network
// of each cycle drawn on the flat sheet (PNG).
int runCrumple(const QStringList& arguments);

} // namespace pf::cli
