// Same seed and inputs give a bit-identical run; another seed gives another run.
#include "Scenes.h"
#include "SheetStats.h"
#include "SheetValidation.h"
#include "Simulation.h"
#include "SymplecticEulerIntegrator.h"

#include <QTest>

using namespace pf;

namespace {

struct RunResult {
    std::uint64_t hash;
    Index breaks;
    double mass;
    std::string valid;
};

RunResult run(std::uint64_t seed, int steps) {
    SceneOptions o;
    o.seed = seed;
    Simulation sim(*makeScene("press", o));
    for (int k = 0; k < steps; ++k)
        if (sim.step() != StepStatus::Ok) return {0, -1, 0, "diverged"};
    const auto st = computeStats(sim.world().sheet);
    return {stateHash(sim.world().sheet), st.breaks, st.totalMass,
            validateSheet(sim.world().sheet)};
}

} // namespace

class TestDeterminism : public QObject {
    Q_OBJECT

  private slots:
    void sameSeedSameHash() {
        const RunResult a = run(1, 500), b = run(1, 500);
        QCOMPARE(a.valid, std::string());
        QVERIFY2(a.breaks > 0, "press must break springs within 500 steps for this to mean much");
        QCOMPARE(a.hash, b.hash);
        QCOMPARE(a.breaks, b.breaks);
    }

    void differentSeedDifferentHash() {
        const RunResult a = run(1, 500), c = run(2, 500);
        QVERIFY(a.hash != c.hash);
    }

    void copiedWorldContinuesIdentically() {
        // A World is plain data: a copy taken mid-run continues exactly like the original.
        Simulation a(*makeScene("press"));
        for (int k = 0; k < 200; ++k) a.step();
        Simulation b(a.world());
        for (int k = 0; k < 200; ++k) {
            a.step();
            b.step();
        }
        QCOMPARE(stateHash(a.world().sheet), stateHash(b.world().sheet));
    }

    void massIsConservedThroughBreaks() {
        Simulation sim(*makeScene("press"));
        const double m0 = totalMass(sim.world().sheet);
        for (int k = 0; k < 500; ++k) sim.step();
        QVERIFY(computeStats(sim.world().sheet).breaks > 0);
        QVERIFY(std::abs(totalMass(sim.world().sheet) - m0) <= 1e-12 * m0);
    }

    void everySceneStepsWithEveryIntegrator_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("integrator");
        for (const auto& s : sceneNames())
            for (const auto& i : integratorNames())
                QTest::newRow(qPrintable(QString::fromStdString(s + "/" + i)))
                    << QString::fromStdString(s) << QString::fromStdString(i);
    }
    void everySceneStepsWithEveryIntegrator() {
        QFETCH(QString, scene);
        QFETCH(QString, integrator);
        World w = *makeScene(scene.toStdString());
        w.params.integrator = integrator.toStdString();
        // Symplectic Euler needs a step inside its stability limit.
        if (integrator == QLatin1String("symplectic"))
            w.params.dt = 0.5 * symplecticStepLimit(w.sheet, w.params);
        Simulation sim(std::move(w));
        // A sanitized build looks for memory errors, which the first steps of each pair
        // already reach (backward Euler's 120 steps took 50 s of it).
        const int steps = PAPERFOLD_TEST_SLOWDOWN > 1 ? 30 : 120;
        for (int k = 0; k < steps; ++k) QCOMPARE(sim.step(), StepStatus::Ok);
        QCOMPARE(validateSheet(sim.world().sheet), std::string());
    }

    void divergedStepIsRolledBack() {
        // Symplectic Euler far beyond its limit blows up; the step reports it and
        // leaves the last good state in place instead of NaN.
        World w = *makeScene("drape");
        w.params.integrator = "symplectic";
        w.params.dt = 1.0 / 30;
        Simulation sim(std::move(w));
        StepStatus status = StepStatus::Ok;
        int k = 0;
        for (; k < 2000 && status == StepStatus::Ok; ++k) status = sim.step();
        QCOMPARE(status, StepStatus::Diverged);
        QCOMPARE(validateSheet(sim.world().sheet), std::string()); // finite, consistent
    }
};

QTEST_APPLESS_MAIN(TestDeterminism)
#include "test_determinism.moc"
