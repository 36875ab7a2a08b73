#pragma once

#include <QString>

namespace pf {

// Why the editor could not open a window here, or an empty string when it can try.
// Qt aborts (exit 134) when it cannot reach a display; this says so first, in one line,
// and points to the headless commands.
QString displayProblem();

} // namespace pf
