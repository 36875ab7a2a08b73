// Editor memory benchmark (not a ctest: it runs for minutes). Drives a real
// MainWindow like test_editor does: ROUNDS times (default 5) it crumples the `press`
// sheet with push strokes of the mouse while the simulation plays for CRUMPLE_SECONDS
// (default 25) of wall time, then triggers File ▸ New ▸ press and prints the process
// RSS (VmRSS) and glibc's in-use heap once the fresh sheet is shown.
//   xvfb-run -a -s "-screen 0 1280x1024x24" build/tests/editor_memory_rounds
// Environment: ROUNDS, CRUMPLE_SECONDS, WARMUP_SECONDS (default 3: one short crumple →
// New before "fresh" is measured; 0 measures from the cold start); PF_TRIM=1 also calls
// malloc_trim(0) after each New and prints the RSS after it (diagnosis: fragmentation vs memory
// still in use); PF_EXIT_AFTER_NEW=1 ends the process right after the last round without cleaning
// up, so that heaptrack reports what is still allocated after New as leaked; PF_SUBDIVISION=n draws
// the surface at subdivision level n instead of the default. Exit status 1 if an RSS after New
// exceeds the fresh start by more than 20 % and keeps growing in three more rounds, or by more
// than 35 %.
#include "BenchWindow.h"
#include "MainWindow.h"
#include "QueuedSignalSpy.h"
#include "RandomStroke.h"
#include "SimulationThread.h"
#include "Viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTest>
#include <cstdio>
#include <cstdlib>
#include <malloc.h>

using namespace pf;

namespace {

double rssMb() {
    QFile f(QStringLiteral("/proc/self/status"));
    if (!f.open(QIODevice::ReadOnly)) return -1;
    for (const QByteArray& line : f.readAll().split('\n'))
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').first().toDouble() / 1024.0;
    return -1;
}

double heapInUseMb() {
    const struct mallinfo2 mi = mallinfo2();
    return double(mi.uordblks + mi.hblkhd) / (1024.0 * 1024.0);
}

double heapHeldMb() { // sbrk/mmap'ed arena space plus mmapped chunks
    const struct mallinfo2 mi = mallinfo2();
    return double(mi.arena + mi.hblkhd) / (1024.0 * 1024.0);
}

// Lets the GUI paint for `ms` and waits for a snapshot published after everything
// queued so far, so the status and the viewport show the current sheet.
SimulationStatus settle(MainWindow& w, int ms) {
    QTest::qWait(ms);
    w.simulation()->sync();
    QueuedSignalSpy spy(w.simulation(), &SimulationThread::snapshotReady);
    w.simulation()->setPlaying(true); // publishes
    QElapsedTimer t;
    t.start();
    while (spy.count() < 1 && t.elapsed() < 5000) QTest::qWait(5);
    // Measure what the viewport holds once it has drawn the new sheet. (Its surface
    // buffers stay about 2 MB whatever the sheet: the editor draws at most
    // kInteractiveTriangles (render/DrawnSurface.h), choosing a coarser level for a finer mesh.)
    QSignalSpy drawn(w.viewport(), &Viewport::frameDrawn);
    t.restart();
    while (drawn.count() < 2 && t.elapsed() < 5000) QTest::qWait(5);
    QTest::qWait(200); // a few repaints with it
    return w.simulation()->status();
}

// Push strokes across the sheet while the simulation plays, for `seconds` of wall time.
void crumple(MainWindow& w, double seconds, QRandomGenerator& rng) {
    Viewport* view = w.viewport();
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < seconds * 1000)
        bench::randomStroke(view, rng, 40, [&] { return t.elapsed() >= seconds * 1000; });
}

} // namespace

int main(int argc, char** argv) {
    Viewport::prepareProcess(); // as the editor does
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("PaperFoldMemoryBench"));
    const int rounds = bench::envInt("ROUNDS", 5);
    const int seconds = bench::envInt("CRUMPLE_SECONDS", 25);
    const bool trim = bench::envInt("PF_TRIM", 0) != 0;
    QRandomGenerator rng(12345);

    MainWindow window;
    if (!bench::showBenchWindow(window, QSize(1000, 700))) return 2;

    if (const char* level = std::getenv("PF_SUBDIVISION")) { // diagnosis: surface size
        RenderOptions o = window.viewport()->renderOptions();
        o.subdivision = std::atoi(level);
        window.viewport()->setRenderOptions(o);
    }
    // "Fresh" is the fresh sheet after one short warm-up round: the first crumple makes
    // Mesa compile the shader variants and size the per-draw pools it keeps for the
    // process, and glibc's main arena keep the pages those draws reuse every frame
    // (malloc_trim gives them back; the next frame takes them again). Measured without
    // the warm-up, that one-time step is +15 to +22 %, the same after 1 round as after 5;
    // what this benchmark looks for is memory that a round leaves behind.
    const int warmup = bench::envInt("WARMUP_SECONDS", 3);
    const double coldRss = rssMb();
    if (warmup > 0) {
        std::printf("cold start: RSS %.1f MB  heap in use %.1f MB\n", coldRss, heapInUseMb());
        crumple(window, warmup, rng);
        window.action("new.press")->trigger();
    }
    const SimulationStatus fresh = settle(window, 1000);
    const double freshRss = rssMb();
    std::printf("fresh: %d vertices  RSS %.1f MB  heap in use %.1f MB  heap held %.1f MB\n",
                fresh.vertices, freshRss, heapInUseMb(), heapHeldMb());
    std::fflush(stdout);

    auto round = [&](int r) {
        crumple(window, seconds, rng);
        const SimulationStatus crumpled = settle(window, 100);
        const double crumpledRss = rssMb();
        window.action("new.press")->trigger();
        const SimulationStatus renewed = settle(window, 1000);
        const double rss = rssMb();
        std::printf(
            "round %d: crumpled %d vertices (%d breaks, step %lld) RSS %.1f MB | after New: %d "
            "vertices  RSS %.1f MB (%+.0f %% of fresh)  heap in use %.1f MB  heap held "
            "%.1f MB",
            r, crumpled.vertices, crumpled.breaks, static_cast<long long>(crumpled.step),
            crumpledRss, renewed.vertices, rss, 100.0 * (rss / freshRss - 1.0), heapInUseMb(),
            heapHeldMb());
        if (trim) {
            malloc_trim(0);
            std::printf("  | after malloc_trim: RSS %.1f MB", rssMb());
        }
        std::printf("\n");
        std::fflush(stdout);
        return rss;
    };
    double worst = freshRss;
    for (int r = 1; r <= rounds; ++r) worst = std::max(worst, round(r));
    // Under load, the GL stack (Mesa and Qt, on the GUI thread's heap) sometimes grows
    // its caches by 15-29 MB in one round and keeps them: measured with malloc_info, all
    // of it in the main arena, none in the simulation thread's, and heaptrack attributes
    // 28 MB of what is live after New to swrast_dri.so, against 1.9 MB for our renderer.
    // That is a step, not a leak: memory that rounds leave behind keeps growing. Over the
    // bar, three more rounds tell which: any of them higher again fails.
    bool grew = false;
    if (worst > 1.2 * freshRss && worst <= 1.35 * freshRss) {
        std::printf("over the bar: 3 more rounds to tell a one-time step from growth\n");
        const double crossed = worst;
        for (int r = rounds + 1; r <= rounds + 3; ++r) {
            const double rss = round(r);
            grew = grew || rss > crossed + 0.02 * freshRss;
            worst = std::max(worst, rss);
        }
    }
    if (bench::envInt("PF_EXIT_AFTER_NEW", 0)) {
        // For heaptrack: what is still allocated now is reported as leaked.
        std::fflush(stdout);
        std::_Exit(0);
    }
    std::printf("worst RSS after New: %.1f MB = %+.0f %% of fresh (bar: +20 %%; up to +35 %% if it "
                "stops growing), %+.0f %% of the cold start\n",
                worst, 100.0 * (worst / freshRss - 1.0), 100.0 * (worst / coldRss - 1.0));
    if (grew) std::printf("FAIL: RSS after New kept growing round after round\n");
    window.close();
    const bool rssOk = worst <= 1.2 * freshRss || (worst <= 1.35 * freshRss && !grew);
    return rssOk ? 0 : 1;
}
