// Damage that settles (docs/model.md, Breaking): the default sheet breaks while it is
// loaded and stops when the load stops, and its mesh stays bounded however long it runs.
#include "Breaking.h"
#include "JacobiScene.h"
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"
#include "TestSheets.h"

#include <QTest>

using namespace pf;

namespace {

void run(Simulation& sim, double seconds) {
    const auto steps = static_cast<int>(std::lround(seconds / sim.world().params.dt));
    for (int k = 0; k < steps; ++k) QCOMPARE(sim.step(), StepStatus::Ok);
}

Index breakEvents(const Simulation& sim) {
    return breaksSince(sim.world().sheet, 0);
}

} // namespace

class TestDamageSettles : public QObject {
    Q_OBJECT

  private slots:
    void aSheetAtRestMakesNoBreaks_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<int>("seed");
        QTest::addColumn<double>("loadedFor"); // seconds until the last contact moves away
        // press: the sphere lifts off at 0.95 s; drop: the sheet has landed by 0.5 s;
        // compress: the pinned edges stop moving at 1.5 s. The paper's jacobi (as the
        // editor ran it, gravity outside the filter) breaks in all three; the default
        // xpbd's paper slides from the sphere and lands whole, so it is held to the bar
        // where it breaks, in compress. A sanitized build, 25 times slower here, runs
        // press with seed 1 only; the Release build runs every row with both seeds.
        const bool sanitized = PAPERFOLD_TEST_SLOWDOWN > 1;
        for (int seed = 1; seed <= (sanitized ? 1 : 2); ++seed) {
            const QByteArray s = QByteArray::number(seed);
            QTest::newRow("jacobi press, seed " + s) << "press"
                                                     << "jacobi" << seed << 0.95;
            if (sanitized) continue;
            QTest::newRow("jacobi drop, seed " + s) << "drop"
                                                    << "jacobi" << seed << 0.5;
            QTest::newRow("jacobi compress, seed " + s) << "compress"
                                                        << "jacobi" << seed << 1.5;
            QTest::newRow("xpbd compress, seed " + s) << "compress"
                                                      << "xpbd" << seed << 1.5;
        }
    }
    void aSheetAtRestMakesNoBreaks() {
        // When the load stops the sheet still springs back and slides for a moment (it
        // breaks a little then: 0-8 breaks in jacobi's press over seeds 1-6, all within
        // 2 s); 2 s later it is at rest, and 10 s of rest break nothing.
        QFETCH(QString, scene);
        QFETCH(QString, integrator);
        QFETCH(int, seed);
        QFETCH(double, loadedFor);
        SceneOptions o;
        o.seed = static_cast<std::uint64_t>(seed);
        World w = *makeScene(qPrintable(scene), o);
        w.params.integrator = integrator.toStdString();
        w.params.gravityOutsideFilter = true;
        Simulation sim(std::move(w));
        run(sim, loadedFor);
        const Index whileLoaded = breakEvents(sim);
        QVERIFY2(whileLoaded > 0, "nothing broke while the sheet was loaded");
        run(sim, 2.0);
        const Index settling = breakEvents(sim) - whileLoaded;
        run(sim, 10.0);
        const Index resting = breakEvents(sim) - whileLoaded - settling;
        qInfo("%s: %lld breaks while loaded, %lld in the 2 s after, %lld in the 10 s of rest",
              qPrintable(scene), static_cast<long long>(whileLoaded),
              static_cast<long long>(settling), static_cast<long long>(resting));
        QCOMPARE(resting, Index(0));
    }

    void aMinuteOfCrumplingKeepsTheMeshBounded_data() {
        QTest::addColumn<QString>("scene");
        QTest::newRow("press") << "press";
        QTest::newRow("compress") << "compress";
    }
    void aMinuteOfCrumplingKeepsTheMeshBounded() {
        QFETCH(QString, scene);
        // Under the sanitizers in jacobi, which breaks at least as much (test::machineryScene).
        World w = test::machineryScene(qPrintable(scene));
        w.params.gravityOutsideFilter = true; // the editor's setting
        Simulation sim(std::move(w));
        const Index start = sim.world().sheet.verts.size();
        // A sanitized build runs 25 times slower; it checks the first 5 s of the minute.
        const double seconds = PAPERFOLD_TEST_SLOWDOWN > 1 ? 5.0 : 60.0;
        run(sim, seconds);
        const Sheet& s = sim.world().sheet;
        qInfo("%s after %.0f s: %lld vertices (%.2f x the start), %lld breaks", qPrintable(scene),
              seconds, static_cast<long long>(s.verts.size()), double(s.verts.size()) / start,
              static_cast<long long>(computeStats(s).breaks));
        QVERIFY(s.verts.size() > start); // it did crumple
        QVERIFY(s.verts.size() < 3 * start);
        // Refinement stops at the paper's crease spacing: no edge a break made is shorter.
        const double spacing = sim.world().params.material.creaseSpacing;
        for (const DamageEvent& ev : s.events) {
            if (!ev.active || ev.kind != EventKind::Break) continue;
            for (Index k : ev.springs)
                QVERIFY(s.materialDistance(s.springs.a[k], s.springs.b[k]) >= spacing);
        }
    }

    void aSheetWokenAfterAnEditBreaksAsAFreshOne() {
        // A step after one the sheet slept through leaves the vertex stars as they were
        // (Simulation::step); the break pass must still see the mesh an edit made
        // meanwhile. So: `compress` to rest, its newest break recovered (as Undo does)
        // while it sleeps (which wakes it), its edges pushed on again (which loads it);
        // step on, and step a Simulation
        // started from the same state beside it. Eq. 10 draws the same probabilities in
        // both, bit for bit, from the first step (stars left stale there gave others).
        // (compress breaks at its own resolution, 19, and not at 11-17, so a sanitized
        // build, 10-25 times slower, would spend a minute or more here.)
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("a sanitized build: compress takes minutes");
        World w = *makeScene("compress");
        w.params.phi = 0.0; // as fragile as Eq. 10 allows
        Simulation slept(std::move(w));
        const int k = test::stepUntilAsleep(slept);
        QVERIFY2(k != test::kStepFailed, "a step failed");
        QVERIFY2(k >= 0, "compress never came to rest");
        Sheet& sheet = slept.world().sheet;
        Index newest = kNone;
        for (Index e = 0; e < static_cast<Index>(sheet.events.size()); ++e)
            if (sheet.events[e].active && sheet.events[e].kind == EventKind::Break &&
                canRecover(sheet, e))
                newest = e;
        QVERIFY2(newest != kNone, "compress made no break to undo");
        const Index vertices = sheet.verts.size();
        QVERIFY(recoverEvent(sheet, newest));
        QVERIFY(sheet.verts.size() < vertices);
        for (PinGroup& g : slept.world().script.pins) g.until = slept.world().time + 0.5;
        Simulation fresh(slept.world());
        float drawn = 0.0f;
        for (int s = 0; s < 120; ++s) {
            QCOMPARE(slept.step(), StepStatus::Ok);
            QCOMPARE(fresh.step(), StepStatus::Ok);
            QCOMPARE(stateHash(slept.world().sheet), stateHash(fresh.world().sheet));
            const std::vector<float>& p = slept.breakProbabilities();
            QVERIFY2(p == fresh.breakProbabilities(), qPrintable(QString::number(s)));
            for (float x : p) drawn = std::max(drawn, x);
        }
        qInfo("asleep after %d steps; the largest probability drawn after the edit %.3g", k,
              double(drawn));
        QVERIFY(!slept.asleep()); // the edit woke it, the push kept it awake
        QVERIFY(drawn > 0.0f);    // and Eq. 10 drew
        QCOMPARE(breakEvents(slept), breakEvents(fresh));
    }
};

QTEST_APPLESS_MAIN(TestDamageSettles)
#include "test_damage_settles.moc"
