// Writes seed inputs for the fuzzers into four folders: valid sheets of each scene
// (small and crumpled), short recordings of editing sessions, reference PNGs of a few
// sizes and formats, and output names.
#include "RecordingFile.h"
#include "SceneScript.h"
#include "Scenes.h"
#include "SheetFile.h"
#include "Simulation.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <numbers>

namespace {

bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    const QDir root(QString::fromLocal8Bit(argv[1]));
    for (const char* sub : {"sheets", "recordings", "images", "patterns"})
        if (!root.mkpath(QLatin1String(sub))) return 1;
    int n = 0;
    // Each scene with the paper's integrator, and with xpbd on a paper that yields
    // easily, so that the seeds carry plastic bends, tool grips and a sleep counter.
    for (const auto& name : pf::sceneNames())
        for (const bool xpbd : {false, true}) {
            pf::SceneOptions o;
            o.resolution = 4;
            pf::World w = *pf::makeScene(name, o);
            if (xpbd) {
                w.params.integrator = "xpbd";
                w.params.material.yieldCurvature = 1.0;
            }
            pf::Simulation sim(std::move(w));
            for (int k = 0; k < 120; ++k) sim.step();
            if (!writeFile(root.filePath(QStringLiteral("sheets/seed%1.paper").arg(n++)),
                           pf::encodeWorld(sim.world())))
                return 1;
        }
    // Short sessions (the fuzzer replays those of at most 32 steps) using every command.
    n = 0;
    for (const auto& name : pf::sceneNames()) {
        pf::SceneOptions o;
        o.resolution = 4;
        pf::EditSession session(*pf::makeScene(name, o));
        const auto& sphere = session.world().sphere;
        session.setTool(sphere.center + pf::Vec3(0.01, -0.02, 0.0), 0.03, true, true);
        session.advance(10);
        session.setTool(sphere.center + pf::Vec3(0.03, -0.02, 0.0), 0.03, true, false);
        session.undoStroke(0);
        session.redoStroke(0);
        pf::SimParams p = session.world().params;
        p.phi = 0.3;
        session.setParams(p);
        session.setTool(sphere.center, 0.02, true, false);
        session.placeToolAtTarget();
        // A fold across the middle (refused where the scene has nothing to fold there).
        const bool folding = session.fold({pf::Vec3(-0.15, 0.0, 0.0), pf::Vec3(0.15, 0.0, 0.0),
                                           std::numbers::pi / 2, false}) == pf::FoldRefusal::None;
        session.advance(10);
        if (!writeFile(root.filePath(QStringLiteral("recordings/seed%1.paperrec").arg(n)),
                       pf::encodeRecording(session.log())))
            return 1;
        // A sheet saved in the middle of a fold: its pin groups have start times.
        if (folding && !writeFile(root.filePath(QStringLiteral("sheets/folding%1.paper").arg(n)),
                                  pf::encodeWorld(session.worldToSave())))
            return 1;
        ++n;
    }
    n = 0;
    for (const QImage::Format format : {QImage::Format_RGB32, QImage::Format_ARGB32,
                                        QImage::Format_Grayscale8, QImage::Format_Indexed8}) {
        QImage image(8 + 3 * n, 6 + n, QImage::Format_ARGB32);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                image.setPixel(x, y, qRgba(x * 30, y * 40, (x + y) * 10, 200 + x));
        image = image.convertToFormat(format);
        if (!image.save(root.filePath(QStringLiteral("images/seed%1.png").arg(n++)), "PNG"))
            return 1;
    }
    n = 0;
    for (const char* text : {"frame_%04d.png", "shot.png", "a%d", "%01d_%", "x_%n.png"})
        if (!writeFile(root.filePath(QStringLiteral("patterns/seed%1").arg(n++)), text)) return 1;
    return 0;
}
