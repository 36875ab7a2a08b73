#pragma once

#include <QStringList>

namespace pf::cli {

// `paperfold simulate ...`: runs a scene headless and reports statistics.
// Returns the process exit code; throws UsageError for bad arguments.
int runSimulate(const QStringList& arguments);

} // namespace pf::cli
