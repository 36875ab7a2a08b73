// The editor's view draws the same picture as the OSMesa path; input that reaches its
// native GL window is the widget's; a receiver of frameDrawn may close it.
// Needs a display: ctest runs it under xvfb-run.
#include "ImageCompare.h"
#include "OffscreenRenderer.h"
#include "RenderCases.h"
#include "Viewport.h"

#include <QMouseEvent>
#include <QSignalSpy>
#include <QTest>
#include <QWindow>

using namespace pf;

namespace {

// Remembers the mouse events a widget receives, with their positions.
class MouseLog : public QObject {
  public:
    std::vector<std::pair<QEvent::Type, QPoint>> events;
    bool eventFilter(QObject*, QEvent* e) override {
        switch (e->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonRelease:
        case QEvent::MouseMove:
            events.emplace_back(e->type(), static_cast<QMouseEvent*>(e)->position().toPoint());
            break;
        default:
            break;
        }
        return false;
    }
};

// The first render case's sheet in a 320 × 200 view, framed; the view is not shown yet.
std::shared_ptr<SheetSnapshot> frameFirstCase(Viewport& view) {
    const test::RenderCase& c = test::renderCases()[0];
    auto snap = std::make_shared<SheetSnapshot>(test::snapshotFor(c));
    view.resize(320, 200);
    view.setSnapshot(snap);
    view.setCamera(test::cameraFor(c, *snap, 320.0 / 200));
    return snap;
}

} // namespace

class TestViewport : public QObject {
    Q_OBJECT

  public:
    static void initMain() { Viewport::prepareProcess(); } // as the editor does

  private slots:
    void editorPathMatchesOsMesaPath_data() {
        QTest::addColumn<int>("index");
        for (int i : {0, 1, 2, 3})
            QTest::newRow(qPrintable(test::renderCases()[static_cast<std::size_t>(i)].name)) << i;
    }
    void editorPathMatchesOsMesaPath() {
        QFETCH(int, index);
        const test::RenderCase& c = test::renderCases()[static_cast<std::size_t>(index)];
        const int w = 480, h = 270;
        auto snap = std::make_shared<SheetSnapshot>(test::snapshotFor(c));
        const OrbitCamera camera = test::cameraFor(c, *snap, double(w) / h);
        RenderOptions options = test::optionsFor(c);
        options.legend = false; // the legend is QPainter text, not the GL path under test

        Viewport view;
        view.setFixedSize(w, h);
        view.setSnapshot(snap);
        view.setCamera(camera);
        view.setRenderOptions(options);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QVERIFY2(view.glError().isEmpty(), qPrintable(view.glError()));
        const QImage editor = view.grabFramebuffer();
        QCOMPARE(editor.size(), QSize(w, h));

        QString error;
        auto offscreen = OffscreenRenderer::create(w, h, &error);
        QVERIFY2(offscreen, qPrintable(error));
        const QImage headless = offscreen->render(*snap, camera, options);
        const ImageDifference d = compareImages(headless, editor);
        qInfo("%s: %.3f %% of pixels differ", qPrintable(c.name), 100 * d.differingFraction);
        if (d.differingFraction > 0.01) {
            editor.save(QDir::temp().filePath(c.name + QStringLiteral(".editor.png")));
            d.map.save(QDir::temp().filePath(c.name + QStringLiteral(".editor-diff.png")));
        }
        QVERIFY(d.differingFraction <= 0.01);
    }

    // The mouse reaches the native window, not the widget: the window hands each event
    // to the widget at the same position, a move without a button only when the widget
    // tracks the mouse, and a press gives the widget the keyboard.
    void inputOnTheWindowReachesTheWidget() {
        Viewport view;
        view.setFixedSize(320, 200);
        view.setFocusPolicy(Qt::StrongFocus);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QWindow* window = view.glWindow();
        QVERIFY(window);
        QTRY_VERIFY(window->isExposed());
        MouseLog log;
        view.installEventFilter(&log);

        QTest::mouseMove(window, QPoint(30, 40)); // no button, not tracking: not delivered
        QTest::mousePress(window, Qt::LeftButton, {}, QPoint(50, 60));
        QTest::mouseMove(window, QPoint(70, 80));
        QTest::mouseRelease(window, Qt::LeftButton, {}, QPoint(70, 80));
        QCOMPARE(log.events.size(), std::size_t(3));
        QCOMPARE(log.events[0], std::make_pair(QEvent::MouseButtonPress, QPoint(50, 60)));
        QCOMPARE(log.events[1], std::make_pair(QEvent::MouseMove, QPoint(70, 80)));
        QCOMPARE(log.events[2], std::make_pair(QEvent::MouseButtonRelease, QPoint(70, 80)));
        QCOMPARE(view.focusWidget(), &view); // the focus the window gets when active

        view.setMouseTracking(true);
        QTest::mouseMove(window, QPoint(90, 100));
        QCOMPARE(log.events.size(), std::size_t(4));
        QCOMPARE(log.events[3], std::make_pair(QEvent::MouseMove, QPoint(90, 100)));
        view.removeEventFilter(&log);
    }

    // frameDrawn comes after the frame is on screen: a receiver that closes the view,
    // with an update still asked for, must not pull the context out from under a paint.
    void closingFromFrameDrawnIsSafe() {
        Viewport view;
        frameFirstCase(view);
        int frames = 0;
        // (A snapshot that draws the same picture asks for no frame; a camera does.)
        connect(&view, &Viewport::frameDrawn, &view, [&] {
            if (++frames < 3) {
                view.setCamera(view.camera()); // asks for the next frame
                return;
            }
            view.setCamera(view.camera());
            view.close();
        });
        view.show();
        QTRY_COMPARE(frames, 3);
        QTest::qWait(200); // the update asked for last arrives after the close
        QCOMPARE(frames, 3);
        QVERIFY(!view.isVisible());
    }

    // A new snapshot is drawn at the next turn of the event loop (Viewport::prepareProcess).
    // An update waited Qt's 5 ms idle time, and the editor drew 40 of the simulation's 59
    // frames a second; the GUI thread was busy 3 ms of each.
    void aNewSnapshotIsDrawnAtTheNextTurnOfTheEventLoop() {
        Viewport view;
        const auto first = frameFirstCase(view);
        QSignalSpy drawn(&view, &Viewport::frameDrawn);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QTRY_VERIFY(drawn.count() >= 1);
        QTest::qWait(50); // anything the first show asked for is drawn
        drawn.clear();

        auto moved = std::make_shared<SheetSnapshot>(*first);
        for (Vec3& x : moved->x) x.y() += 0.01; // lifted 1 cm: another picture
        view.setSnapshot(moved);
        QCoreApplication::processEvents(); // once, waiting for nothing
        QCOMPARE(drawn.count(), 1);
        QCOMPARE(view.snapshot(), moved.get());
    }

    // 4× MSAA halves the frame rate where the CPU draws: the view goes without it there,
    // and keeps it on a GPU.
    void multisamplingOnlyWhereAGpuDraws() {
        const QByteArray renderer = Viewport::glRenderer().toLower();
        QVERIFY(!renderer.isEmpty());
        const bool software = renderer.contains("llvmpipe") || renderer.contains("softpipe") ||
                              renderer.contains("swrast");
        qInfo("GL renderer: %s", renderer.constData());
        QCOMPARE(Viewport::viewFormat().samples(), software ? 0 : 4);
        QCOMPARE(Viewport::requiredFormat().samples(), 4);
    }
};

QTEST_MAIN(TestViewport)
#include "test_viewport.moc"
