// Rendering benchmark (not a test: timings are reported, never asserted).
//   bench_render offscreen   one 1920×1080 frame of `press` at subdivision 3 via OSMesa
//   bench_render viewport    the editor's QOpenGLWidget at 1280×720 (needs a display,
//                            e.g. xvfb-run), redrawn continuously while press crumples
// Prints the median of several runs.
#include "OffscreenRenderer.h"
#include "Scenes.h"
#include "SheetSnapshot.h"
#include "Simulation.h"
#include "Viewport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <cstdio>

using namespace pf;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

OrbitCamera fitted(const SheetSnapshot& s, double aspect) {
    OrbitCamera c = *namedView("iso");
    c.fitPoints(s.x, aspect);
    return c;
}

int offscreen() {
    Simulation sim(*makeScene("press"));
    for (int k = 0; k < 300; ++k) sim.step();
    const SheetSnapshot snap = makeSnapshot(sim);
    QString error;
    auto r = OffscreenRenderer::create(1920, 1080, &error);
    if (!r) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    RenderOptions o;
    o.subdivision = 3;
    const OrbitCamera cam = fitted(snap, 1920.0 / 1080);
    r->render(snap, cam, o); // warm-up: shader compilation, first allocation
    std::vector<double> t;
    for (int i = 0; i < 9; ++i) {
        QElapsedTimer timer;
        timer.start();
        const QImage img = r->render(snap, cam, o);
        t.push_back(timer.nsecsElapsed() * 1e-9);
    }
    std::printf(
        "offscreen 1920x1080 subdivision 3: median %.3f s per frame (min %.3f, max %.3f), %s\n",
        median(t), *std::min_element(t.begin(), t.end()), *std::max_element(t.begin(), t.end()),
        qPrintable(r->glVersion()));
    return 0;
}

int viewport() {
    Simulation sim(*makeScene("press"));
    Viewport view;
    view.resize(1280, 720);
    RenderOptions o;
    o.subdivision = 3;
    view.setRenderOptions(o);
    auto first = std::make_shared<SheetSnapshot>(makeSnapshot(sim));
    view.setCamera(fitted(*first, 1280.0 / 720));
    view.setSnapshot(first);
    view.show();
    std::vector<double> frameGaps;
    QElapsedTimer clock;
    clock.start();
    qint64 last = -1;
    // Each swapped frame: advance the crumpling sheet by one 60 Hz frame (4 steps) and ask
    // for the next frame, so the viewport redraws as fast as it can.
    QObject::connect(&view, &Viewport::frameDrawn, [&] {
        const qint64 now = clock.nsecsElapsed();
        if (last >= 0) frameGaps.push_back((now - last) * 1e-9);
        last = now;
        for (int k = 0; k < 4; ++k) sim.step();
        view.setSnapshot(std::make_shared<SheetSnapshot>(makeSnapshot(sim)));
        if (frameGaps.size() >= 240) qApp->quit();
    });
    QTimer::singleShot(60000, qApp, &QApplication::quit);
    qApp->exec();
    if (frameGaps.empty()) {
        std::fprintf(stderr, "no frames were drawn\n");
        return 1;
    }
    const double m = median(frameGaps);
    std::printf("viewport 1280x720 subdivision 3, press crumpling: median %.1f ms per frame (%.1f "
                "fps) over %zu frames\n",
                1e3 * m, 1.0 / m, frameGaps.size());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "offscreen") {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        QGuiApplication app(argc, argv);
        return offscreen();
    }
    if (mode == "viewport") {
        Viewport::prepareProcess(); // as the editor does
        QApplication app(argc, argv);
        return viewport();
    }
    std::fprintf(stderr, "usage: bench_render offscreen|viewport\n");
    return 2;
}
