// Editor endurance benchmark (not a ctest: it runs for minutes). Drives a real
// MainWindow as a user's mouse would: push strokes one after another, each starting
// where the `press` sheet shows, for PUSH_SECONDS (default 120) of wall time, then hands off for
// REST_SECONDS (default 10); PUSH_SHEET=file.paper opens that sheet first (a large one
// measures the editor at scale); PUSH_THREADS=n steps on n threads (default: the
// editor's setting); PUSH_WINDOW=WxH sizes the window; PUSH_SHOT=file.png saves the window at the
// end, PUSH_SAVE=file.paper the sheet, PUSH_RECORDING=file.paperrec the session (which
// `paperfold replay` steps again headless, bit for bit, to time or profile the simulation
// without the view drawing beside it). Every 10 s it prints the sheet's size, the step's cost,
// frames drawn per second and how much simulated time passed per second of wall time: the editor
// keeps up with real time while that stays at 1.
//   xvfb-run -a -s "-screen 0 1280x1024x24" build/tests/editor_push_minutes
// Exit status 1 if the simulation fell below 0.9 of real time in any 10 s.
#include "BenchWindow.h"
#include "MainWindow.h"
#include "RandomStroke.h"
#include "RecordingFile.h"
#include "SheetSnapshot.h"
#include "SimulationThread.h"
#include "Viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QSignalSpy>
#include <QTest>
#include <cstdio>
#include <cstdlib>

using namespace pf;

namespace {

// Where a random vertex of the sheet shows in the view: a user pushes the paper where it
// is, wherever earlier strokes have moved it.
QPoint onTheSheet(const Viewport* view, QRandomGenerator& rng) {
    const SheetSnapshot* snap = view->snapshot();
    if (!snap || snap->x.empty()) return view->rect().center();
    const Vec3& x = snap->x[rng.bounded(static_cast<int>(snap->x.size()))];
    const OrbitCamera& camera = view->camera();
    const Eigen::Vector4d clip = camera.projection(double(view->width()) / view->height()) *
                                 camera.view() * Eigen::Vector4d(x.x(), x.y(), x.z(), 1.0);
    const double nx = clip.x() / clip.w(), ny = clip.y() / clip.w();
    return QPoint(static_cast<int>((0.5 + 0.5 * nx) * view->width()),
                  static_cast<int>((0.5 - 0.5 * ny) * view->height()));
}

} // namespace

int main(int argc, char** argv) {
    Viewport::prepareProcess(); // as the editor does
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("PaperFoldPushBench"));
    const int pushSeconds = bench::envInt("PUSH_SECONDS", 120);
    const int restSeconds = bench::envInt("REST_SECONDS", 10);
    QRandomGenerator rng(2026);

    MainWindow window;
    // PUSH_WINDOW=WxH sizes the window (default 1280x720; the docks take part of it).
    QSize windowSize(1280, 720);
    if (const char* size = std::getenv("PUSH_WINDOW")) {
        const QStringList wh = QString::fromLatin1(size).split(QLatin1Char('x'));
        const QSize asked = wh.size() == 2 ? QSize(wh[0].toInt(), wh[1].toInt()) : QSize();
        if (asked.width() < 320 || asked.height() < 240) {
            std::fprintf(stderr, "PUSH_WINDOW must be WxH, at least 320x240 (got %s)\n", size);
            return 2;
        }
        windowSize = asked;
    }
    if (!bench::showBenchWindow(window, windowSize)) return 2;
    if (const char* sheet = std::getenv("PUSH_SHEET")) {
        window.showError = [](const QString& message) {
            std::fprintf(stderr, "%s\n", qPrintable(message));
        };
        if (!window.openFile(QString::fromLocal8Bit(sheet))) return 2;
    }
    QElapsedTimer t;
    t.start();
    const double dt = 1.0 / 240.0; // the editor's step
    SimulationThread* sim = window.simulation();
    if (const int threads = bench::envInt("PUSH_THREADS", 0); threads > 0) sim->setThreads(threads);
    sim->setPlaying(true);

    QSignalSpy frames(window.viewport(), &Viewport::frameDrawn);
    // Snapshots the GUI thread took from the simulation, and the view's paint per frame
    // drawn (the GUI thread's drawing; llvmpipe's rasterising threads and the swap, and
    // the GUI thread's other work, are not in it).
    QSignalSpy snapshots(sim, &SimulationThread::snapshotReady);
    double paintSeconds = 0.0;
    QObject::connect(window.viewport(), &Viewport::frameDrawn,
                     [&] { paintSeconds += window.viewport()->lastFrameSeconds(); });
    double worst = 1e9;
    std::int64_t lastStep = sim->status().step;
    QElapsedTimer wall;
    wall.start();
    std::printf("window %dx%d, view %dx%d\n", window.width(), window.height(),
                window.viewport()->width(), window.viewport()->height());
    std::printf(
        "   wall  phase  vertices  springs  breaks (/s)  step µs   fps  snaps/s  paint ms  sim s "
        "per wall s\n");
    const auto report = [&](const char* phase) {
        const SimulationStatus st = sim->status();
        const double seconds = wall.restart() * 1e-3;
        const double pace = (st.step - lastStep) * dt / seconds;
        std::printf("%7.0f  %5s  %8d  %7d  %6d (%3d)  %7.0f  %4.0f  %7.0f  %8.1f  %.2f\n",
                    t.elapsed() * 1e-3, phase, st.vertices, st.springs, st.breaks,
                    st.breaksLastSecond, st.stepSeconds * 1e6, frames.count() / seconds,
                    snapshots.count() / seconds,
                    frames.empty() ? 0.0 : 1e3 * paintSeconds / frames.count(), pace);
        std::fflush(stdout);
        worst = std::min(worst, pace);
        lastStep = st.step;
        frames.clear();
        snapshots.clear();
        paintSeconds = 0.0;
    };
    QElapsedTimer phase;
    phase.start();
    for (int chunk = 0; chunk < pushSeconds / 10; ++chunk) {
        QElapsedTimer c;
        c.start();
        while (c.elapsed() < 10'000)
            bench::randomStroke(
                window.viewport(), rng, 40, [&] { return c.elapsed() >= 10'000; },
                onTheSheet(window.viewport(), rng));
        report("push");
    }
    for (int chunk = 0; chunk < restSeconds / 10; ++chunk) {
        QTest::qWait(10'000);
        report("rest");
    }
    std::printf("slowest 10 s: %.2f of real time\n", worst);
    if (const char* shot = std::getenv("PUSH_SHOT"))
        window.grab().save(QString::fromLocal8Bit(shot));
    if (const char* save = std::getenv("PUSH_SAVE")) window.saveFile(QString::fromLocal8Bit(save));
    if (const char* recording = std::getenv("PUSH_RECORDING")) {
        QString error;
        if (!saveRecording(sim->copyRecording(), QString::fromLocal8Bit(recording), &error))
            std::fprintf(stderr, "%s\n", qPrintable(error));
    }
    window.close();
    return worst >= 0.9 ? 0 : 1;
}
