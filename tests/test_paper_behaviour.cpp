// What real paper does that the scorecard's numbers do not show on their own, checked on
// the xpbd integrator with office paper: a fold pressed past the yield curvature stays
// while a gentle bend springs back; a tool pushing a loose sheet across the desk drags
// it whole, and slides over one whose far edge is held; a sleeping sheet runs no break
// pass and wakes when gravity changes; a finer sheet than the scorecard's stays within the stretch
// bound where pins or the tool hold it; where pins or a hand hold it up, the projection converges
// in about one Newton iteration a step.
#include "EditSession.h"
#include "Scenes.h"
#include "SheetBuilder.h"
#include "SheetFile.h"
#include "SheetStats.h"
#include "Simulation.h"
#include "TestData.h"
#include "TestSheets.h"
#include "XpbdIntegrator.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

using namespace pf;

namespace {

// A strip 12 cm × 3 cm with 1 cm cells, lying in the x-z plane and folded about the
// line x = 6 cm by `angle` (0: flat), floating without gravity.
World foldedStrip(double angle) {
    SheetSpec spec;
    spec.width = 0.12;
    spec.length = 0.03;
    spec.columns = 13;
    spec.rows = 4;
    World w;
    w.sheet = buildRectangleSheet(spec);
    w.groundEnabled = false;
    w.params.integrator = "xpbd";
    w.params.gravity = 0.0;
    w.params.breaking = false;
    w.params.hinges = false;
    const double fold = spec.width / 2.0;
    for (Vec3& x : w.sheet.verts.x) {
        const double u = x.x() - (-spec.width / 2.0) - fold; // from the fold line
        if (u > 0.0)
            x = Vec3(fold - spec.width / 2.0 + u * std::cos(angle), u * std::sin(angle), x.z());
    }
    return w;
}

// The angle between the strip's two end cells (0 when flat).
double foldAngle(const Sheet& s) {
    const auto& x = s.verts.x;
    const Vec3 left = x[1] - x[0];
    const Vec3 right = x[12] - x[11];
    return std::acos(std::clamp(left.normalized().dot(right.normalized()), -1.0, 1.0));
}

World pushScene(bool holdFarEdge) {
    World w = *makeScene("press");
    w.params.integrator = "xpbd";
    // The scene's sphere comes down near the near edge and ploughs an S toward the far
    // edge, 18 cm in 0.8 s, then lifts off.
    // Real paper is never quite flat; a faint wave of 0.5 mm lets a compressed sheet
    // choose where to rise, as the compress scene's does.
    for (Vec3& x : w.sheet.verts.x)
        x.y() = 0.0005 * (1.0 + std::sin(std::numbers::pi * x.z() / 0.1485)) / 2.0;
    if (holdFarEdge) test::holdFarEdge(w, 19);
    return w;
}

struct PushResult {
    double highest = 0.0;    // highest vertex, m
    double centreMove = 0.0; // horizontal move of the centre of mass, m
    double stretch = 0.0;    // largest stretch during the push
};

PushResult push(bool holdFarEdge) {
    Simulation sim(pushScene(holdFarEdge));
    const Vec3 before = centreOfMass(sim.world().sheet);
    PushResult r;
    for (int k = 0; k < 240; ++k) {
        if (sim.step() != StepStatus::Ok) break;
        for (const Vec3& x : sim.world().sheet.verts.x) r.highest = std::max(r.highest, x.y());
        r.stretch = std::max(r.stretch, computeStats(sim.world().sheet).maxStretch);
    }
    Vec3 moved = centreOfMass(sim.world().sheet) - before;
    moved.y() = 0.0;
    r.centreMove = moved.norm();
    return r;
}

} // namespace

class TestPaperBehaviour : public QObject {
    Q_OBJECT
  private slots:
    void aSharpFoldStaysAndAGentleBendSpringsBack() {
        // A fold of 150° across one 1 cm cell bends the paper at about 2 sin(75°)/1 cm =
        // 190/m, past office paper's yield of 100/m; 30° is 52/m, elastic.
        const double deg = std::numbers::pi / 180.0;
        Simulation sharp(foldedStrip(150.0 * deg));
        Simulation gentle(foldedStrip(30.0 * deg));
        for (int k = 0; k < 480; ++k) {
            QCOMPARE(sharp.step(), StepStatus::Ok);
            QCOMPARE(gentle.step(), StepStatus::Ok);
        }
        const double kept = foldAngle(sharp.world().sheet) / deg;
        const double left = foldAngle(gentle.world().sheet) / deg;
        qInfo("after 2 s: the 150° fold keeps %.1f°, the 30° bend keeps %.1f°", kept, left);
        // The fold keeps what went past the yield, less what springs back: the crease's
        // elastic part, whose limit falls toward κ_y w_c / s as it yields (a few degrees
        // to a few tens). The gentle bend keeps nothing. (Kept 40.6° while the plate's sum
        // stencils yielded only at twice the curvature and pulled the fold back.)
        QVERIFY(kept > 100.0);
        QVERIFY(left < 5.0);
    }

    void aLooseSheetIsDraggedAndAHeldOneIsNot() {
        const PushResult loose = push(false);
        const PushResult held = push(true);
        qInfo("loose: centre moved %.1f mm, highest point %.1f mm; held: moved %.1f mm, "
              "highest %.1f mm; largest stretch %.3f %% / %.3f %%",
              1e3 * loose.centreMove, 1e3 * loose.highest, 1e3 * held.centreMove,
              1e3 * held.highest, 100 * loose.stretch, 100 * held.stretch);
        // The grip drags the loose sheet with the tool and it stays flat on the desk;
        // the held sheet stays where it is and the tool slides over it. (Real paper
        // would rise in a buckle ahead of the tool; here the edges resist compression
        // up to their own buckling load, more than the 2 N tool's grip: docs/material.md.)
        QVERIFY(loose.centreMove > 0.05);
        QVERIFY(loose.highest < 0.003);
        QVERIFY(held.centreMove < 0.01);
        QVERIFY(loose.stretch < 0.01);
        QVERIFY(held.stretch < 0.01);
    }

    void aFinerSheetStaysWithinTheStretchBound_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("resolution");
        QTest::addColumn<double>("bound");
        // Before the projection iterated to 0.3 % where pins and the tool hold the paper,
        // these peaked at 2.86 % and 1.03 %; now 0.46 % and 0.30 %. drape's bound is half
        // issue 9's 1 %, so that falling back fails it by more than a rounding.
        QTest::newRow("press, resolution 40, under the tool")
            << QStringLiteral("press") << 40 << 0.01;
        QTest::newRow("drape, resolution 30, from two pins")
            << QStringLiteral("drape") << 30 << 0.005;
    }
    void aFinerSheetStaysWithinTheStretchBound() {
        QFETCH(QString, scene);
        QFETCH(int, resolution);
        QFETCH(double, bound);
        SceneOptions finer;
        finer.resolution = resolution;
        World w = *makeScene(scene.toStdString(), finer);
        w.params.integrator = "xpbd";
        Simulation sim(std::move(w));
        double worst = 0.0, worstRms = 0.0;
        for (int k = 0; k < 240; ++k) { // 1 s: press's tool bites and ploughs, drape swings
            QCOMPARE(sim.step(), StepStatus::Ok);
            const SheetStats st = computeStats(sim.world().sheet);
            worst = std::max(worst, st.maxStretch);
            worstRms = std::max(worstRms, st.rmsStretch);
        }
        qInfo("%ld vertices: largest stretch %.3f %%, largest RMS %.4f %%",
              static_cast<long>(sim.world().sheet.verts.size()), 100 * worst, 100 * worstRms);
        QVERIFY2(worst <= bound, qPrintable(QString::number(worst)));
        QVERIFY2(worstRms <= 0.001, qPrintable(QString::number(worstRms)));
    }

    // Where pins or a hand hold the paper up, the fast projection must keep the stretch
    // within half of issue 9's 1 % in about one Newton iteration a step. Undamped on the
    // nearly singular J W Jᵀ of a flat triangle mesh it took 3.5 in the drape and 2.6 for
    // the held corner (kDampedProjectionCompliance).
    void aHeldSheetIsProjectedInAboutOneNewtonIteration_data() {
        QTest::addColumn<QString>("held");
        QTest::newRow("drape, resolution 30, from two pins") << QStringLiteral("pins");
        QTest::newRow("a corner lifted 8 cm by the hand and held") << QStringLiteral("hand");
    }
    void aHeldSheetIsProjectedInAboutOneNewtonIteration() {
        QFETCH(QString, held);
        std::optional<EditSession> session;
        if (held == "pins") {
            SceneOptions finer;
            finer.resolution = 30;
            World w = *makeScene("drape", finer);
            w.params.integrator = "xpbd";
            session.emplace(std::move(w));
        } else {
            session.emplace(makeEditorScene("press", SceneOptions{}, 0.03));
            session->advance(60); // settled on the desk
        }
        EditSession& s = *session;
        const Vec3 corner = s.world().sheet.verts.x[0];
        const Vec3 lifted = corner + Vec3(0.0, 0.08, 0.0);
        if (held == "hand") s.grab(corner, true, true);
        const auto work = [&] {
            const auto* xpbd = dynamic_cast<const XpbdIntegrator*>(&s.simulation().integrator());
            return xpbd ? xpbd->projectionWork().newtonIterations : -1;
        };
        QVERIFY(work() >= 0); // the default integrator, xpbd
        // The hand's first second lifts, and its second is measured; the drape is
        // measured from the let-go, as it swings wide (the air stills it within seconds).
        const int measuredFrom = held == "hand" ? 60 : 0;
        double worst = 0.0;
        std::int64_t before = work();
        constexpr int kFrames = 120, kStepsPerFrame = 4; // 2 s at 240 steps a second
        for (int frame = 0; frame < kFrames; ++frame) {
            if (held == "hand") s.grab(lifted, true, false);
            QCOMPARE(s.advance(kStepsPerFrame), StepStatus::Ok);
            if (frame == measuredFrom - 1) before = work();
            if (frame >= measuredFrom)
                worst = std::max(worst, computeStats(s.world().sheet).maxStretch);
        }
        const double newton = double(work() - before) / ((kFrames - measuredFrom) * kStepsPerFrame);
        qInfo("per step: %.2f Newton iterations; largest stretch %.3f %%", newton, 100 * worst);
        QVERIFY2(worst <= 0.005, qPrintable(QString::number(worst)));
        // The sub-steps alone leave it stretched more than the projection allows.
        QVERIFY2(newton > 0.0, "the projection never ran");
        QVERIFY2(newton <= 2.0, qPrintable(QString::number(newton)));
    }

    // Tissue's crumple-cycles, saved at step 724 (3.02 s) as its rim gathers the sheet. In
    // the next two steps the projection's Newton iterations wander: they run out, the
    // Gauss-Seidel sweeps and a second start follow (93 and 96 iterations), and in the
    // second of them Newton wanders from its second start too and left the sheet at
    // 3.1 % stretch; the sweeps alone, as long as they take, bring it to 0.76 %
    // (kStubbornSweeps). (The state this test stepped from before, saved at 29.05 s, no
    // longer wanders once the plate's sum stencils yield as the others do.)
    void aStepWhereNewtonWandersStillEndsWithinTheBound() {
        std::optional<World> state = test::packedState("tissue-newton-stall.paper.qz");
        QVERIFY(state);
        QCOMPARE(state->params.integrator, std::string("xpbd"));
        Simulation sim(std::move(*state));
        const auto newton = [&] {
            return dynamic_cast<const XpbdIntegrator&>(sim.integrator())
                .projectionWork()
                .newtonIterations;
        };
        double worst = 0.0;
        std::int64_t most = 0;
        for (int k = 0; k < 3; ++k) {
            const std::int64_t before = newton();
            QCOMPARE(sim.step(), StepStatus::Ok);
            most = std::max(most, newton() - before);
            worst = std::max(worst, computeStats(sim.world().sheet).maxStretch);
        }
        qInfo("largest stretch over 3 steps: %.3f %%; most Newton iterations in a step: %lld",
              100 * worst, static_cast<long long>(most));
        // The saved state still makes Newton wander: its iterations ran out and it started
        // again (were it to stop wandering here, this test would no longer test the sweeps).
        QVERIFY2(most > kMaxProjectionIterations, qPrintable(QString::number(most)));
        QVERIFY2(worst <= kStretchBound, qPrintable(QString::number(100 * worst)));
    }

    // Office paper pinned at two corners, pushed by the tool (tests/data/README.md). In the
    // next step the projection's Newton iterations swing the worst stretch between two
    // light crease vertices, 0.9-2 %: the sixth reached 0.89 %, and none did better. Past
    // its 16 iterations it went on while the state it was in was over 1 %, all 48, and
    // then went back to the sixth's. It ends at its best once that is within the bound.
    void aProjectionThatSwingsEndsAtItsBestOnceItsIterationsAreDone() {
        std::optional<World> state = test::packedState("pinned-push-newton-swing.paper.qz");
        QVERIFY(state);
        QCOMPARE(state->params.integrator, std::string("xpbd"));
        QVERIFY(state->sphere.active);
        Simulation sim(std::move(*state));
        sim.setThreads(1);
        QCOMPARE(sim.step(), StepStatus::Ok);
        const std::int64_t newton =
            dynamic_cast<const XpbdIntegrator&>(sim.integrator()).projectionWork().newtonIterations;
        const double stretch = computeStats(sim.world().sheet).maxStretch;
        qInfo("%lld Newton iterations, %.3f %% stretch", static_cast<long long>(newton),
              100 * stretch);
        QVERIFY2(stretch <= kStretchBound, qPrintable(QString::number(100 * stretch)));
        QVERIFY2(stretch > kProjectedStretch, "the state no longer swings: the test tests nothing");
        QVERIFY2(newton <= kProjectionIterations + 1, qPrintable(QString::number(newton)));
    }

    // A user's sheet, folded in two at 90° (it fell shut) and then mountain-folded
    // through the stack, φ 0.57, ψ 0.71, saved from the editor while it cycled, minutes
    // after the let-go. Where the creases cross, light vertices the breaks inserted went round a
    // cycle of four steps 0.57 mm across, the still rule read their positions, and the
    // sheet never fell asleep: for minutes the editor stepped it at 9-15 ms a step, a
    // quarter of real time, with nothing to see moving. Read on each vertex's mean
    // position, the cycle goes nowhere and the sheet sleeps.
    void aSheetWhoseCreasesCycleInPlaceFallsAsleep() {
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        std::optional<World> state = test::packedState("folded-twice-cycle.paper.qz");
        QVERIFY(state);
        Simulation sim(std::move(*state));
        const std::vector<Vec3> start = sim.world().sheet.verts.x;
        double movedInAStep = 0.0, wandered = 0.0;
        int steps = 0;
        for (; steps < 2400 && !sim.asleep(); ++steps) {
            const std::vector<Vec3> before = sim.world().sheet.verts.x;
            QCOMPARE(sim.step(), StepStatus::Ok);
            const auto& x = sim.world().sheet.verts.x;
            for (std::size_t i = 0; i < x.size(); ++i) {
                movedInAStep = std::max(movedInAStep, (x[i] - before[i]).norm());
                wandered = std::max(wandered, (x[i] - start[i]).norm());
            }
        }
        qInfo("asleep after %.2f s; the most a vertex moved in a step %.2f mm, from where it "
              "started %.2f mm",
              steps / 240.0, 1e3 * movedInAStep, 1e3 * wandered);
        // It was not lying still: its vertices kept moving by more than the still reach.
        QVERIFY(movedInAStep > kStillReach);
        // It sleeps within the still rule's second and a half of the cycle's averaging,
        // having gone nowhere a user could see, and stays asleep.
        QVERIFY2(sim.asleep(), "the sheet never fell asleep");
        QVERIFY(steps < 480);
        QVERIFY(wandered < 2e-3);
        for (int k = 0; k < 240; ++k) QCOMPARE(sim.step(), StepStatus::Ok);
        QVERIFY(sim.asleep());
    }

    // A user's sheet of card, pinned at two corners and crumpled (a helper's editor
    // session, 2026-12-01): one vertex of it swung 0.9 mm up and down and the paper round
    // it less, in a cycle of 1.1 s, for as long as it was left, and the editor stepped it
    // at a fifth of real time with nothing to see moving. Its mean position over eight
    // steps still spans 0.80 mm; over the last half second, 0.10 mm, and the sheet
    // sleeps.
    void aPinnedCardThatSwingsInPlaceFallsAsleep() {
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        std::optional<World> state = test::packedState("pinned-card-swing.paper.qz");
        QVERIFY(state);
        QCOMPARE(QString::fromStdString(state->params.material.name), QStringLiteral("card"));
        Simulation sim(std::move(*state));
        const auto& x = sim.world().sheet.verts.x;
        std::vector<Vec3> lowest = x, highest = x;
        int steps = 0;
        for (; steps < 2400 && !sim.asleep(); ++steps) {
            QCOMPARE(sim.step(), StepStatus::Ok);
            for (std::size_t i = 0; i < x.size(); ++i) {
                lowest[i] = lowest[i].cwiseMin(x[i]);
                highest[i] = highest[i].cwiseMax(x[i]);
            }
        }
        double swing = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i)
            swing = std::max(swing, (highest[i] - lowest[i]).norm());
        qInfo("asleep after %.2f s; the widest a vertex swung %.2f mm", steps / 240.0, 1e3 * swing);
        // It was not lying still: a vertex swung farther than the still reach.
        QVERIFY(swing > kStillReach);
        QVERIFY2(sim.asleep(), "the sheet never fell asleep");
        QVERIFY(steps < 480);
        QVERIFY(swing < 2e-3);
        for (int k = 0; k < 240; ++k) QCOMPARE(sim.step(), StepStatus::Ok);
        QVERIFY(sim.asleep());
    }

    // Office paper in the editor, pinned at two corners: one push stroke rolled it into
    // a tube, and the next presses the tool into the tube's side, drawn taut between
    // the pins (tests/data/README.md). After the projection the tool pushed the paper
    // out of itself and stretched it 1.1-1.5 % after every step, over issue 9's 1 %. It
    // now stops short where the paper is taut, as paper stops a hand.
    void aToolPressedIntoTautPaperStopsShort() {
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        std::optional<World> state = test::packedState("pinned-tube-pressed.paper.qz");
        QVERIFY(state);
        EditSession session(std::move(*state));
        const auto* xpbd = dynamic_cast<const XpbdIntegrator*>(&session.simulation().integrator());
        QVERIFY(xpbd);
        constexpr double radius = 0.03;
        double worst = 0.0, inside = 0.0;
        int stopped = 0;
        // The stroke goes on as the probe that saved the sheet drove it: 20 frames of
        // four steps, the target 3.3 mm further along x each frame.
        for (int frame = 41; frame <= 60; ++frame) {
            session.setTool(Vec3(-0.12 + 0.2 * frame / 60.0, 0.4 * radius, 0.03), radius, true,
                            true);
            for (int k = 0; k < 4; ++k) {
                QCOMPARE(session.advance(1), StepStatus::Ok);
                const World& w = session.world();
                worst = std::max(worst, computeStats(w.sheet).maxStretch);
                for (const Vec3& x : w.sheet.verts.x)
                    inside = std::max(inside, radius - (x - w.sphere.center).norm());
                if (const auto at = xpbd->toolHeldAt()) {
                    ++stopped;
                    QCOMPARE(*at, w.sphere.center); // where the world keeps it
                }
            }
        }
        qInfo("stretch at most %.3f %%; the tool stopped short in %d of 80 steps; paper at "
              "most %.2g m inside it",
              100.0 * worst, stopped, inside);
        QVERIFY(stopped > 0);
        QVERIFY(worst <= kStretchBound);
        QVERIFY(inside <= 0.0);
    }

    // The `drape` sheet hanging from its two pins, pushed from the front and dragged
    // sideways, as a user of the editor pushes it. After the projection the paper lay
    // inside the tool where the step had begun (the projection pulls back what the
    // sub-steps stretched round the tool, and the sheet swings back against it), so the
    // tool could not stop short of it: pushed out from there, the paper stretched 1.42 %
    // at the worst step of these two strokes (16 % in an editor session). The paper now
    // pushes the tool back out of it.
    void aToolPushedIntoAHangingSheetStretchesItNoFurther() {
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession session(*makeScene("drape"));
        QCOMPARE(session.advance(1440), StepStatus::Ok); // 6 s: hanging still
        const World& w = session.world();
        double front = 0.0; // the sheet hangs in a plane of constant z
        for (const Vec3& x : w.sheet.verts.x) front += x.z() / w.sheet.verts.size();
        const double radius = w.sphere.radius;
        double worst = 0.0, worstRms = 0.0;
        int stopped = 0;
        for (int stroke = 0; stroke < 2; ++stroke) {
            const double y = 0.15 + 0.04 * stroke, x0 = -0.08 + 0.05 * stroke;
            const Vec3 start(x0, y, front - radius - 0.02);
            session.setTool(start, radius, true, false);
            session.placeToolAtTarget();
            session.setTool(start, radius, true, true);
            // A quarter second in, to 6 cm past the sheet, then across at 0.3 m/s.
            for (int frame = 0; frame < 60; ++frame) {
                const double t = frame / 60.0, in = std::min(1.0, 4.0 * t);
                session.setTool(Vec3(x0 + 0.3 * t, y, start.z() + in * (radius + 0.08)), radius,
                                true, true);
                for (int k = 0; k < 4; ++k) {
                    QCOMPARE(session.advance(1), StepStatus::Ok);
                    const SheetStats stats = computeStats(w.sheet);
                    worst = std::max(worst, stats.maxStretch);
                    worstRms = std::max(worstRms, stats.rmsStretch);
                    if (session.simulation().integrator().toolHeldAt()) ++stopped;
                }
            }
            session.setTool(Vec3(x0, y, front - radius - 0.05), radius, true, false);
            QCOMPARE(session.advance(30), StepStatus::Ok);
        }
        qInfo("stretch at most %.3f %%, RMS at most %.4f %%; the tool stopped short in %d of "
              "480 steps",
              100.0 * worst, 100.0 * worstRms, stopped);
        QVERIFY(stopped > 0); // the paper was drawn taut against the tool
        QVERIFY2(worst <= kStretchBound, qPrintable(QString::number(100 * worst)));
        QVERIFY2(worstRms <= 0.001, qPrintable(QString::number(100 * worstRms)));
    }

    void aSleepingSheetDoesNotBreak() {
        // The gate itself: once the sheet has come to rest it falls asleep, stays asleep
        // for 10 s (nothing wakes it) and Eq. 10 draws nothing in that time.
        World w = *makeScene("press");
        w.params.integrator = "xpbd";
        w.params.phi = 0.0; // as fragile as Eq. 10 allows
        Simulation sim(std::move(w));
        const int k = test::stepUntilAsleep(sim);
        QVERIFY2(k != test::kStepFailed, "a step failed");
        QVERIFY2(k >= 0, "the sheet never came to rest");
        const auto breaks = computeStats(sim.world().sheet).breaks;
        for (int s = 0; s < 2400; ++s) QCOMPARE(sim.step(), StepStatus::Ok);
        qInfo("asleep after %.2f s with %ld breaks; 10 s later %ld breaks", k / 240.0,
              static_cast<long>(breaks), static_cast<long>(computeStats(sim.world().sheet).breaks));
        QVERIFY(sim.asleep());
        QCOMPARE(computeStats(sim.world().sheet).breaks, breaks);
    }

    void aSleepingSheetWakesWhenGravityChanges() {
        // A load that changes is not rest: the strip asleep in weightlessness falls as
        // soon as gravity is turned on (the cantilever check ramps its load up from
        // nothing, and a stiff strip that slept through it stayed flat).
        Simulation sim(foldedStrip(0.0));
        const int k = test::stepUntilAsleep(sim);
        QVERIFY2(k != test::kStepFailed, "a step failed");
        QVERIFY2(k >= 0, "the weightless strip never came to rest");
        const double before = centreOfMass(sim.world().sheet).y();
        sim.world().params.gravity = 9.81;
        constexpr int kSteps = 60; // 0.25 s
        for (int s = 0; s < kSteps; ++s) QCOMPARE(sim.step(), StepStatus::Ok);
        const double t = kSteps * sim.world().params.dt;
        const double fell = before - centreOfMass(sim.world().sheet).y();
        qInfo("asleep after %d steps; fell %.2f mm in %.2f s (free fall %.2f mm)", k, 1e3 * fell, t,
              1e3 * 0.5 * 9.81 * t * t);
        QVERIFY(!sim.asleep());
        QCOMPARE_GE(fell, 0.99 * 0.5 * 9.81 * t * t);
        QCOMPARE_LE(fell, 1.01 * 0.5 * 9.81 * t * t);
    }
};

QTEST_APPLESS_MAIN(TestPaperBehaviour)
#include "test_paper_behaviour.moc"
