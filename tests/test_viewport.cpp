// The editor's QOpenGLWidget path draws the same picture as the OSMesa path.
// Needs a display: ctest runs it under xvfb-run.
#include "ImageCompare.h"
#include "OffscreenRenderer.h"
#include "RenderCases.h"
#include "Viewport.h"

#include <QTest>

using namespace pf;

class TestViewport : public QObject {
    Q_OBJECT

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
};

QTEST_MAIN(TestViewport)
#include "test_viewport.moc"
