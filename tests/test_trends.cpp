// The behaviour the paper reports (§5, Fig. 10 and 11), over several seeds.
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"

#include <QTest>

using namespace pf;

namespace {

struct Outcome {
    long breaks = 0;
    long inserted = 0; // vertices added by breaking
};

Outcome runSeeds(const char* scene, double phi, double psi, int seeds, int steps,
                 const char* integrator = "jacobi") {
    Outcome total;
    for (int seed = 1; seed <= seeds; ++seed) {
        SceneOptions o;
        o.seed = static_cast<std::uint64_t>(seed);
        World w = *makeScene(scene, o);
        const Index v0 = w.sheet.verts.size();
        w.params.phi = phi;
        w.params.psi = psi;
        w.params.integrator = integrator;
        Simulation sim(std::move(w));
        for (int k = 0; k < steps; ++k)
            if (sim.step() != StepStatus::Ok) break;
        total.breaks += computeStats(sim.world().sheet).breaks;
        total.inserted += sim.world().sheet.verts.size() - v0;
    }
    return total;
}

} // namespace

class TestTrends : public QObject {
    Q_OBJECT

  private slots:
    void fragilityOneBreaksLessThanZero() {
        // Fig. 10: larger φ gives stiffer paper. At φ = 1 a flat region cannot break
        // at all (Eq. 10), at φ = 0 curvature is ignored.
        const Outcome soft = runSeeds("press", 0.0, 0.25, 4, 240);
        const Outcome stiff = runSeeds("press", 1.0, 0.25, 4, 240);
        qInfo("press, 4 seeds, 1 s: breaks at phi=0: %ld, at phi=1: %ld", soft.breaks,
              stiff.breaks);
        QVERIFY(soft.breaks >= 20);
        QVERIFY(stiff.breaks < soft.breaks / 2);
    }

    void stiffPaperKeepsTheFragilityTrend() {
        // Fig. 10 with office paper's real stiffness (xpbd): a sheet pushed on the desk
        // slides or arches and hardly breaks, so the trend is measured where stiff paper
        // does crease, in the first gather of crumple-cycles (2.5 s). Eq. 10 reads the
        // arc there (docs/model.md).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        const Outcome soft = runSeeds("crumple-cycles", 0.0, 0.25, 2, 600, "xpbd");
        const Outcome stiff = runSeeds("crumple-cycles", 1.0, 0.25, 2, 600, "xpbd");
        qInfo("xpbd, crumple-cycles, 2 seeds, 2.5 s: breaks at phi=0: %ld, at phi=1: %ld",
              soft.breaks, stiff.breaks);
        QVERIFY(soft.breaks >= 100);
        QVERIFY(stiff.breaks < soft.breaks / 2);
    }

    void smallPsiBreaksRecursively() {
        // Fig. 11 / Eq. 11: with ψ = 1 the halves of a broken edge are at rest length;
        // as ψ falls they stay compressed and break again. Measured in compress, where
        // the compression is sustained. (ψ = 0.25 against ψ = 1 is within the seed
        // noise under this project's reading; see docs/model.md.)
        const Outcome recursive = runSeeds("compress", 0.5, 0.0, 2, 240);
        const Outcome rested = runSeeds("compress", 0.5, 1.0, 2, 240);
        qInfo("compress, 2 seeds, 1 s: inserted vertices at psi=0: %ld, at psi=1: %ld",
              recursive.inserted, rested.inserted);
        QVERIFY(rested.inserted > 0);
        QVERIFY(recursive.inserted > 2 * rested.inserted);
    }
};

QTEST_APPLESS_MAIN(TestTrends)
#include "test_trends.moc"
