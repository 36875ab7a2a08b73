// Crumpling measured against real paper (docs/model.md, "Crumpling measured against real
// paper"): the crumple-cycles scene, the crease network it leaves, and the logarithmic
// growth of crease length that repeatedly crumpled paper shows.
#include "Breaking.h"
#include "CreaseNetwork.h"
#include "CrumpleCycles.h"
#include "Normals.h"
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"
#include "TestSheets.h"

#include <QTest>
#include <cmath>

using namespace pf;

namespace {

std::vector<Vec3> rimPositions(const World& w) {
    std::vector<Vec3> x;
    for (Index i : w.script.pins.front().vertices) x.push_back(w.sheet.verts.x[i]);
    return x;
}

} // namespace

class TestCrumpleCycles : public QObject {
    Q_OBJECT

  private slots:
    void aBreaksCreaseIsTheLineAcrossItsEdge() {
        // The quad's edge i-j runs along x from (-0.5, 0) to (0.5, 0); r = (0, 0.5) and
        // l = (0, -0.5). Broken, it inserts n at (0, 0): the crease r-n-l is 1 long and
        // straight, one run.
        Sheet s = test::makeFoldedQuad();
        std::vector<Vec3> normals;
        computeVertexNormals(s, normals);
        const Index first = breakEdge(s, 0, normals, 1.0, 0);
        CreaseNetwork net = measureCreases(s);
        QCOMPARE(net.totalLength, 1.0);
        QCOMPARE(net.segments.size(), std::size_t(1));
        QCOMPARE(net.segments.front(), 1.0);
        // The half i-n breaks too, at n2 = (-0.25, 0): its crease r-n2-l adds
        // 2 sqrt(0.25² + 0.5²). The four crease edges close a loop r-n-l-n2-r; it turns by
        // 127° at l and at r (corners: runs end there) and by 53° at n2 (a run goes on), so
        // the runs are r-n-l and l-n2-r.
        computeVertexNormals(s, normals);
        breakEdge(s, s.events[first].springs[0], normals, 1.0, 1);
        net = measureCreases(s);
        const double side = std::hypot(0.25, 0.5);
        QVERIFY(std::abs(net.totalLength - (1.0 + 2.0 * side)) < 1e-12);
        QCOMPARE(net.segments.size(), std::size_t(2));
        QVERIFY(std::abs(net.segments[0] - 2.0 * side) < 1e-12);
        QVERIFY(std::abs(net.segments[1] - 1.0) < 1e-12);
        // A recovered break is no crease any more.
        QVERIFY(recoverEvent(s, 1));
        QCOMPARE(measureCreases(s).totalLength, 1.0);
    }

    void logarithmicFitRecoversItsLaw() {
        std::vector<double> law;
        for (int n = 1; n <= 10; ++n) law.push_back(2.5 + 0.75 * std::log(n));
        const LogarithmicFit fit = fitLogarithmic(law);
        QVERIFY(std::abs(fit.a - 2.5) < 1e-12);
        QVERIFY(std::abs(fit.b - 0.75) < 1e-12);
        QVERIFY(std::abs(fit.r2 - 1.0) < 1e-12);
        // A straight line is not logarithmic: the fit says so.
        std::vector<double> line;
        for (int n = 1; n <= 10; ++n) line.push_back(n);
        QVERIFY(fitLogarithmic(line).r2 < 0.95);
    }

    void gatheringInAndPullingOutBringsTheRimBack() {
        // At a step that divides none of the scene's times, the rim still comes back to
        // where it started after each cycle: a draw moves for the part of a step inside
        // its window.
        World w = *makeScene("crumple-cycles");
        w.params.integrator = "jacobi"; // the rim is pinned: any integrator; the fast one
        w.params.dt = 1.0 / 237.7;
        w.params.breaking = false;
        const std::vector<Vec3> start = rimPositions(w);
        QCOMPARE(w.script.pins.size(), std::size_t(2 * kCrumpleCycles));
        Simulation sim(std::move(w));
        while (sim.world().time < kCrumpleGather + 0.5 * kCrumpleSqueeze)
            QCOMPARE(sim.step(), StepStatus::Ok);
        // Gathered: every rim vertex is kCrumpleFraction as far from the cycle's point.
        const Vec3 centre = sim.world().script.pins.front().pivot;
        const std::vector<Vec3> gathered = rimPositions(sim.world());
        for (std::size_t k = 0; k < start.size(); ++k) {
            const Vec3 expected = centre + kCrumpleFraction * (start[k] - centre);
            QVERIFY2((gathered[k] - expected).norm() < 1e-12, qPrintable(QString::number(k)));
        }
        while (sim.world().time < 2 * kCrumpleCycleSeconds - 0.1)
            QCOMPARE(sim.step(), StepStatus::Ok);
        const std::vector<Vec3> back = rimPositions(sim.world());
        for (std::size_t k = 0; k < start.size(); ++k)
            QVERIFY2((back[k] - start[k]).norm() < 1e-12, qPrintable(QString::number(k)));
    }

    void creaseLengthGrowsLikeTheLogOfCycles() {
        // Gottesman et al. 2018: a sheet crumpled and flattened again and again adds less
        // crease each time, about as a + b ln n. Two seeds, ten cycles.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        for (const std::uint64_t seed : {1, 2}) {
            SceneOptions o;
            o.seed = seed;
            World w = *makeScene("crumple-cycles", o);
            w.params.integrator = "jacobi"; // as `paperfold crumple` runs it
            w.params.gravityOutsideFilter = true;
            const CrumpleReport r = runCrumpleCycles(std::move(w), kCrumpleCycles);
            QCOMPARE(QString::fromStdString(r.error), QString());
            QCOMPARE(r.cycles.size(), std::size_t(kCrumpleCycles));
            std::vector<double> added;
            double before = 0.0;
            for (const CrumpleCycle& c : r.cycles) {
                added.push_back(c.creaseLength - before);
                before = c.creaseLength;
            }
            QString line;
            for (double a : added) line += QString::number(a, 'f', 3) + QLatin1Char(' ');
            qInfo("seed %d: L(10) = %.3f m, added per cycle %s; fit a = %.3f, b = %.3f, R2 = %.3f",
                  int(seed), before, qPrintable(line), r.fit.a, r.fit.b, r.fit.r2);
            // It creases every cycle, never heals...
            for (double a : added) QVERIFY(a >= 0.0);
            // ...and adds less and less: the last five cycles together add less than the
            // first two, and the fit is logarithmic.
            const double firstTwo = added[0] + added[1];
            const double lastFive = added[5] + added[6] + added[7] + added[8] + added[9];
            QVERIFY2(lastFive < firstTwo, qPrintable(line));
            QVERIFY(r.fit.b > 0.0);
            QVERIFY2(r.fit.r2 > 0.9, qPrintable(QString::number(r.fit.r2)));
            QVERIFY(!r.segments.empty());
        }
    }

    void theFirstCycleStaysWithinTheStretchBound() {
        // Issue 9's bound, in every step of the first gather, squeeze, pull and hold with
        // office paper (`xpbd`, the default). The sub-steps leave up to 68 % stretch on
        // the light vertices of a gathered sheet's creases, and the projection used to
        // end on it: it gave up after 16 Newton iterations while the stretch was still
        // 14 %, kept a damped iteration that crawled 4 % an iteration, or ended above the
        // best state it had reached; and a break's relaxation stopped after 32 sweeps
        // with 1.4 % left, or, moving one ring round the new vertices, held 8.5 % of a
        // break's 31 %. Over seeds 1-3 the worst step read 1.69 %, 3.19 % and 1.05 %
        // then, and 0.39 %, 0.30 % and 0.30 % now (docs/speed.md).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        for (const std::uint64_t seed : {1, 2, 3}) {
            SceneOptions o;
            o.seed = seed;
            Simulation sim(*makeScene("crumple-cycles", o));
            QCOMPARE(sim.world().params.integrator, std::string("xpbd"));
            double worst = 0.0, worstRms = 0.0;
            while (sim.world().time < kCrumpleCycleSeconds - 1e-9) {
                QCOMPARE(sim.step(), StepStatus::Ok);
                const SheetStats st = computeStats(sim.world().sheet);
                worst = std::max(worst, st.maxStretch);
                worstRms = std::max(worstRms, st.rmsStretch);
            }
            qInfo("seed %d: largest stretch %.3f %%, largest RMS stretch %.4f %%, %d breaks",
                  int(seed), 100.0 * worst, 100.0 * worstRms,
                  int(computeStats(sim.world().sheet).breaks));
            QVERIFY(computeStats(sim.world().sheet).breaks > 0); // it did crumple
            QVERIFY2(worst <= 0.01, qPrintable(QString::number(100.0 * worst)));
            QVERIFY2(worstRms <= 0.001, qPrintable(QString::number(100.0 * worstRms)));
        }
    }
};

QTEST_APPLESS_MAIN(TestCrumpleCycles)
#include "test_crumple_cycles.moc"
