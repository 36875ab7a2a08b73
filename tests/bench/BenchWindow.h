#pragma once

#include <QSize>

namespace pf {
class MainWindow;
}

namespace pf::bench {

// An integer from the environment, or `fallback` when it is unset or empty.
int envInt(const char* name, int fallback);

// Shows `window` at `size` as the editor benchmarks drive it (errors printed, nothing
// asked) and waits until it shows its first sheet. False if it never appeared.
bool showBenchWindow(MainWindow& window, QSize size);

} // namespace pf::bench
