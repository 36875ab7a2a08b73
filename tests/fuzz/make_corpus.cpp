// Writes seed inputs for the fuzzer: valid sheets of each scene, small and crumpled.
#include "Scenes.h"
#include "SheetFile.h"
#include "Simulation.h"

#include <QFile>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    int n = 0;
    for (const auto& name : pf::sceneNames()) {
        pf::SceneOptions o;
        o.resolution = 4;
        pf::Simulation sim(*pf::makeScene(name, o));
        for (int k = 0; k < 120; ++k) sim.step();
        QFile f(QString::fromLocal8Bit(argv[1]) + QStringLiteral("/seed%1.paper").arg(n++));
        if (!f.open(QIODevice::WriteOnly)) return 1;
        f.write(pf::encodeWorld(sim.world()));
    }
    return 0;
}
