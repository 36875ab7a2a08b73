#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold replay FILE.paperrec ...`: does a recorded editing session again, headless.
int runReplay(const QStringList& arguments);

} // namespace pf::cli
