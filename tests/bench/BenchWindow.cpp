#include "BenchWindow.h"

#include "MainWindow.h"
#include "Viewport.h"

#include <QElapsedTimer>
#include <QMessageBox>
#include <QTest>
#include <cstdio>
#include <cstdlib>

namespace pf::bench {

int envInt(const char* name, int fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::atoi(v) : fallback;
}

bool showBenchWindow(MainWindow& window, QSize size) {
    window.resize(size);
    window.showError = [](const QString& m) { std::fprintf(stderr, "error: %s\n", qPrintable(m)); };
    window.askToSave = [] { return QMessageBox::Discard; };
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return false;
    QElapsedTimer t;
    t.start();
    while (!window.viewport()->snapshot() && t.elapsed() < 10000) QTest::qWait(10);
    if (!window.viewport()->glError().isEmpty())
        std::fprintf(stderr, "GL: %s\n", qPrintable(window.viewport()->glError()));
    return true;
}

} // namespace pf::bench
