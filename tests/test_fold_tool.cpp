// The Fold tool (sim/FoldPlan.h, EditSession::fold): a fold drawn across the sheet is
// carried round, pressed and let go, and the crease the model makes keeps it; it is an
// undo step, replays bit for bit, and a sheet saved mid-fold finishes the fold.
#include "EditSession.h"
#include "FoldAngle.h"
#include "FoldPlan.h"
#include "FoldWatch.h"
#include "JacobiScene.h"
#include "Material.h"
#include "RecordingFile.h"
#include "Scenes.h"
#include "SheetFile.h"
#include "SheetSnapshot.h"
#include "SheetStats.h"

#include <Eigen/SVD>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

using namespace pf;

namespace {

constexpr double kPi = std::numbers::pi;

// The editor's sheet (office A4 on the desk, the editor's settings, or another
// integrator), let settle 0.5 s.
EditSession editorSession(bool damage = true, const std::string& integrator = {}) {
    World w = makeEditorScene("press", SceneOptions{}, 0.03);
    w.params.breaking = w.params.hinges = damage;
    if (!integrator.empty())
        w.params.integrator = integrator;
    else
        test::affordMachinery(w); // the carry's machinery
    EditSession s(std::move(w));
    [&] { QCOMPARE(s.advance(120), StepStatus::Ok); }();
    return s;
}

// Steps the session, which must say nothing of a fold all the while (neither that it
// opened again nor that it left paper unfolded).
void saysNothingOfTheFoldFor(EditSession& s, int steps) {
    for (int k = 0; k < steps; ++k) {
        QCOMPARE(s.advance(1), StepStatus::Ok);
        QVERIFY(!s.takeFoldTurnedBack());
        QVERIFY(!s.takeFoldLeftBehind());
    }
}

// Across the middle of the sheet, from edge to edge and beyond (the line is a line).
FoldRequest acrossTheMiddle(double angle = kPi, bool mountain = false) {
    return {Vec3(-0.15, 0.0, 0.0), Vec3(0.15, 0.0, 0.0), angle, mountain};
}

void advanceSeconds(EditSession& s, double seconds) {
    const double end = s.world().time + seconds;
    while (s.world().time < end) QCOMPARE(s.advance(1), StepStatus::Ok);
}

// Steps until the fold is let go; returns the seconds it took.
double runUntilLetGo(EditSession& s) {
    const double start = s.world().time;
    while (s.folding()) {
        const StepStatus status = s.advance(1);
        if (status != StepStatus::Ok) return -1.0;
    }
    return s.world().time - start;
}

double length() {
    return SceneOptions{}.length;
}

// Plays the fold's pin groups alone, each pinned vertex moving as its group says and
// nothing else moving, and returns the largest stretch they ask of the paper between a
// carried vertex and one that stays (held by the lift, or lying beyond the band on the
// desk): max |x_c − x_r| / max(|X_c − X_r|, their distance before) − 1 over pairs less
// than 4 cm apart in the paper.
double stretchTheCarryAsks(World w, const FoldRequest& request, const FoldPlan& plan) {
    Sheet& sheet = w.sheet;
    auto& V = sheet.verts;
    std::vector<char> carried(static_cast<std::size_t>(V.size()), 0);
    for (const PinGroup& g : plan.motions)
        if (g.turnRate != 0.0)
            for (Index i : g.vertices) carried[static_cast<std::size_t>(i)] = 1;
    for (const PinGroup& g : plan.motions)
        for (Index i : g.vertices) V.pinned[i] = 1;
    // Across the line as drawn on the desk (the test's lines lie in it): what stays is the
    // paper beyond the band on the side the flap is not on.
    const Vec3 along = (request.to - request.from).normalized();
    const Vec3 across = Vec3::UnitY().cross(along);
    const auto sideOf = [&](Index i) { return (V.x[i] - request.from).dot(across); };
    std::vector<Index> stays, carry;
    for (Index i = 0; i < V.size(); ++i)
        if (carried[static_cast<std::size_t>(i)]) carry.push_back(i);
    const double flapSide = carry.empty() ? 1.0 : (sideOf(carry.front()) > 0.0 ? 1.0 : -1.0);
    // Lifted off the desk, what stays is what the lift holds; the rest of that side is
    // free, and goes where the paper takes it.
    bool lifted = false;
    for (const PinGroup& g : plan.motions) lifted = lifted || g.turnRate == 0.0;
    for (Index i = 0; i < V.size(); ++i)
        if (-flapSide * sideOf(i) > kFoldBand && (!lifted || V.pinned[i])) stays.push_back(i);
    std::vector<double> before;
    before.reserve(carry.size() * stays.size());
    for (Index c : carry)
        for (Index r : stays) before.push_back((V.x[c] - V.x[r]).norm());
    w.script.pins = plan.motions;
    SphereTool sphere;
    const double h = w.params.dt;
    double worst = 0.0;
    for (double t = w.time; t < plan.release - h; t += h) {
        applyScript(w.script, t, h, sheet, sphere);
        for (Index i = 0; i < V.size(); ++i)
            if (V.pinned[i]) V.x[i] += h * V.v[i];
        for (std::size_t a = 0; a < carry.size(); ++a)
            for (std::size_t b = 0; b < stays.size(); ++b) {
                const Index c = carry[a], r = stays[b];
                const double apart = sheet.materialDistance(c, r);
                // Paper the soft springs had already stretched is not asked for more.
                const double was = std::max(apart, before[a * stays.size() + b]);
                if (apart < 0.04) worst = std::max(worst, (V.x[c] - V.x[r]).norm() / was - 1.0);
            }
    }
    return worst;
}

// A sheet folded in two and in two again lies in four layers, one quarter of the
// material sheet each; laid flat, each is its material quarter turned about the vertical
// (mirrored or not). Returns how far the layers are turned apart, in degrees: the spread
// of their turns, each fitted to the quarter's vertices (least squares, Kabsch) and taken
// modulo a half turn (a quarter carried over twice is turned by one).
double layersTurnedApart(const Sheet& sheet) {
    const auto& V = sheet.verts;
    Vec2 low = V.X.front(), high = V.X.front();
    for (const Vec2& X : V.X) {
        low = low.cwiseMin(X);
        high = high.cwiseMax(X);
    }
    const Vec2 middle = 0.5 * (low + high);
    double least = 1e9, most = -1e9, first = 0.0;
    for (int quarter = 0; quarter < 4; ++quarter) {
        const auto in = [&](Index i) {
            return (V.X[i].x() > middle.x()) == bool(quarter & 1) &&
                   (V.X[i].y() > middle.y()) == bool(quarter & 2);
        };
        Vec2 material = Vec2::Zero(), laid = Vec2::Zero();
        int n = 0;
        for (Index i = 0; i < V.size(); ++i)
            if (in(i)) {
                material += V.X[i];
                laid += Vec2(V.x[i].x(), V.x[i].z());
                ++n;
            }
        material /= n;
        laid /= n;
        Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
        for (Index i = 0; i < V.size(); ++i)
            if (in(i))
                covariance +=
                    (V.X[i] - material) * (Vec2(V.x[i].x(), V.x[i].z()) - laid).transpose();
        const Eigen::JacobiSVD<Eigen::Matrix2d> svd(covariance,
                                                    Eigen::ComputeFullU | Eigen::ComputeFullV);
        const Eigen::Matrix2d turn = svd.matrixV() * svd.matrixU().transpose();
        double degrees = std::atan2(turn(1, 0), turn(0, 0)) * 180.0 / kPi;
        // Modulo a half turn, measured from the first quarter's (a spread across ±90°
        // would otherwise read as nearly a half turn).
        if (quarter == 0) first = degrees;
        degrees -= first;
        while (degrees > 90.0) degrees -= 180.0;
        while (degrees <= -90.0) degrees += 180.0;
        least = std::min(least, degrees);
        most = std::max(most, degrees);
    }
    return most - least;
}

} // namespace

class TestFoldTool : public QObject {
    Q_OBJECT

  private slots:
    void aValleyFoldIsCarriedRoundAndStays() {
        EditSession s = editorSession();
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        QVERIFY(s.folding());
        // Half way round the flap stands up: carried, not placed.
        advanceSeconds(s, 0.75);
        const double halfWay = foldAngle(s.world().sheet, length());
        const double took = 0.75 + runUntilLetGo(s);
        const double letGo = foldAngle(s.world().sheet, length());
        const auto ended = s.takeFinished();
        advanceSeconds(s, 2.0);
        const double later = foldAngle(s.world().sheet, length());
        qInfo("half way %.1f deg, let go after %.2f s at %.1f deg, 2 s later %.1f deg; %d breaks "
              "and hinges in the fold",
              halfWay, took, letGo, later, ended ? ended->events : -1);
        QVERIFY(halfWay > 60.0 && halfWay < 120.0);
        // A half turn at kFoldTurnRate, pressed kFoldPress.
        QVERIFY(std::abs(took - (kPi / kFoldTurnRate + kFoldPress)) < 0.02);
        QVERIFY(letGo > 170.0);
        QVERIFY(later > 170.0);
        QVERIFY(ended);
        QCOMPARE(ended->kind, EditSession::StrokeKind::Fold);
        QVERIFY(ended->events > 0);             // the crease is the model's breaks and hinges
        QVERIFY(!s.takeFinished());             // reported once
        QVERIFY(s.world().script.pins.empty()); // the carry is gone with the fold
    }

    void aFoldedSheetComesToRest() {
        // Paper that does not stretch (xpbd), folded and let go, lies still within a
        // second (issue 9's rest bound: kinetic energy under 1e-9 J, no vertex faster than
        // 1 mm/s) and keeps its fold. Its fold's vertices kept a sub-step cycle of 2 cm/s
        // while their positions stayed the same: the sheet never slept.
        // Physics only (the Release build runs it; CI time under the sanitizers).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(true, "xpbd");
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        runUntilLetGo(s);
        advanceSeconds(s, 1.0);
        const auto& V = s.world().sheet.verts;
        // Sleeping zeroes the velocities, so the positions are checked too: a sheet put to
        // sleep while it still drifted would pass the energy bound.
        const std::vector<Vec3> settled = V.x;
        double energy = 0.0, fastest = 0.0;
        for (int step = 0; step < 480; ++step) {
            QCOMPARE(s.advance(1), StepStatus::Ok);
            double e = 0.0;
            for (Index i = 0; i < V.size(); ++i) {
                e += 0.5 * V.m[i] * V.v[i].squaredNorm();
                fastest = std::max(fastest, V.v[i].norm());
            }
            energy = std::max(energy, e);
        }
        const double angle = foldAngle(s.world().sheet, length());
        qInfo("1-3 s after the fold was let go: kinetic energy up to %.2e J, fastest vertex "
              "%.2e m/s, fold at %.1f deg",
              energy, fastest, angle);
        QVERIFY(energy < 1e-9);
        QVERIFY(fastest < 1e-3);
        QVERIFY(angle > 170.0);
        QVERIFY(s.simulation().asleep());
        QCOMPARE(V.x.size(), settled.size());
        double moved = 0.0;
        for (std::size_t i = 0; i < settled.size(); ++i)
            moved = std::max(moved, (V.x[i] - settled[i]).norm());
        QVERIFY2(moved < 1e-4, qPrintable(QStringLiteral("moved %1 m").arg(moved)));
    }

    void withoutBreaksAndHingesTheSheetSpringsBackFlat() {
        // The same carry without the crease model: nothing keeps the fold. Physics only,
        // no code path the other cases miss: left to the Release build (CI time). In the
        // paper's jacobi: under xpbd the flap stays on the rest (179.5 deg), since with
        // no self-contact nothing lifts it where bending has no lever (docs/material.md).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(false, "jacobi");
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        runUntilLetGo(s);
        QVERIFY(foldAngle(s.world().sheet, length()) > 170.0);
        advanceSeconds(s, 10.0);
        const double later = foldAngle(s.world().sheet, length());
        qInfo("without breaks and hinges: %.1f deg 10 s after it was let go", later);
        QVERIFY(later < 30.0);
    }

    void aPartialFoldIsHeldAtItsAngle() {
        // Pressed flat first (an unpressed crease springs open), then opened back to the
        // angle and held there until it is let go. Physics only (CI time, as above).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession();
        QCOMPARE(s.fold(acrossTheMiddle(kPi / 2)), FoldRefusal::None);
        const double release = s.world().script.pins.back().release;
        advanceSeconds(s, 1.6); // round and pressed
        QVERIFY(foldAngle(s.world().sheet, length()) > 170.0);
        while (s.world().time < release - 0.1) QCOMPARE(s.advance(1), StepStatus::Ok);
        const double held = foldAngle(s.world().sheet, length());
        qInfo("90 degree fold held at %.1f deg (measured between the halves' quarter lines)", held);
        // Measured between quarter lines, not at the hinge: jacobi reads 95, xpbd 78.
        QVERIFY(std::abs(held - 90.0) < 15.0);
    }

    void theCarryNeverPullsTheFlapAwayFromThePaperThatStays() {
        // Turned about a line 3 mm off the paper, the flap swung away from the line before
        // it came over, and the paper between it and the rest had to stretch: by 1.4 %
        // for a mountain fold across a sheet on the desk (the solve let 17.6 % through),
        // by 81 % for a second fold across the first, whose axis the first fold's
        // rounded crease had tilted 14 mm off the paper at the line's far end (8,500 %).
        // The fold now turns in the paper's own plane, and holds only paper that lies in
        // it (kHeldSlope): the pins alone ask at most half the square of that slope.
        EditSession s = editorSession();
        const FoldRequest across[] = {acrossTheMiddle(),
                                      acrossTheMiddle(kPi, true),
                                      acrossTheMiddle(kPi / 2, true),
                                      {Vec3(0.0, 0, -0.2), Vec3(0.0, 0, 0.2), kPi, false}};
        for (const FoldRequest& r : across) {
            const FoldPlan plan = planFold(s.world(), r);
            QCOMPARE(plan.refusal, FoldRefusal::None);
            const double asked = stretchTheCarryAsks(s.world(), r, plan);
            qInfo("a %s fold to %.0f deg asks %.3f %% of the paper",
                  r.mountain ? "mountain" : "valley", r.angle * 180.0 / kPi, 100.0 * asked);
            QVERIFY(asked < 0.5 * kHeldSlope * kHeldSlope + 1e-4);
        }
        // Across a first fold, mountain: the sheet is lifted, and both layers are held.
        // Folded the first time by paper that does not stretch: the soft springs' first
        // fold (the sanitizer builds' machinery) leaves the layers stretched and rumpled,
        // and no rise asks less than 0.7 % of them.
        s = editorSession(true, "xpbd");
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        runUntilLetGo(s);
        advanceSeconds(s, 2.0);
        const FoldRequest again{Vec3(0.01, 0, -0.2), Vec3(0.0, 0, 0.2), kPi, true};
        const FoldPlan second = planFold(s.world(), again);
        QCOMPARE(second.refusal, FoldRefusal::None);
        const double asked = stretchTheCarryAsks(s.world(), again, second);
        qInfo("a second fold across the first asks %.3f %% of the paper", 100.0 * asked);
        QVERIFY(asked < 0.5 * kHeldSlope * kHeldSlope + 1e-4);
    }

    void aFoldDoesNotStretchThePaper() {
        // Issue 9's bound holds while the flap is carried, pressed and let go: a mountain
        // fold on the desk stretched the paper in its band 17.6 % when the carry turned it
        // about a line 3 mm off the paper. Physics only (CI time under the sanitizers).
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        for (const bool mountain : {false, true}) {
            EditSession s = editorSession(true, "xpbd");
            QCOMPARE(s.fold(acrossTheMiddle(kPi, mountain)), FoldRefusal::None);
            double worst = 0.0;
            while (s.folding()) {
                QCOMPARE(s.advance(1), StepStatus::Ok);
                worst = std::max(worst, computeStats(s.world().sheet).maxStretch);
            }
            qInfo("%s fold: largest stretch %.2f %%", mountain ? "mountain" : "valley",
                  100.0 * worst);
            QVERIFY(worst < 0.01);
        }
    }

    void theFoldGoesTowardTheViewerOrAway_data() {
        QTest::addColumn<QString>("integrator");
        QTest::newRow("jacobi") << QStringLiteral("jacobi");
        QTest::newRow("xpbd") << QStringLiteral("xpbd");
    }

    void theFoldGoesTowardTheViewerOrAway() {
        // In the air (no desk under it), seen from above, a mountain fold carries the flap
        // below the paper and a valley fold above it; seen from below, the other way.
        // Heights are taken from the rest of the paper (its mean, vertices breaks added
        // included), which the Fold tool holds where it lies; before it did, nothing held
        // it in the air and the carried flap swung it the other way, by 7 cm in 0.75 s for
        // paper that does not stretch (xpbd), by 6 mm for the soft springs (jacobi).
        QFETCH(QString, integrator);
        const std::pair<bool, bool> kinds[] = {
            {false, false}, {true, false}, {true, true}, {false, true}};
        for (auto [mountain, fromBelow] : kinds) {
            World w = makeEditorScene("press", SceneOptions{}, 0.03);
            w.groundEnabled = false;
            w.params.gravity = 0.0;
            w.params.integrator = integrator.toStdString();
            EditSession s(std::move(w));
            FoldRequest request = acrossTheMiddle(kPi, mountain);
            if (fromBelow) request.viewer = -Vec3::UnitY();
            QCOMPARE(s.fold(request), FoldRefusal::None);
            // The flap, carried in kCarrySegments turns, and the rest, held where it lies.
            const auto& groups = s.world().script.pins;
            QCOMPARE(groups.size(), std::size_t(kCarrySegments + 1));
            const std::vector<Index> flap = groups.front().vertices;
            for (std::size_t g = 0; g < kCarrySegments; ++g) QVERIFY(groups[g].vertices == flap);
            QVERIFY(!groups.back().vertices.empty());
            for (Index i : groups.back().vertices)
                QVERIFY(std::find(flap.begin(), flap.end(), i) == flap.end());
            advanceSeconds(s, 0.75);
            const auto& x = s.world().sheet.verts.x;
            std::vector<bool> inFlap(x.size(), false);
            for (Index i : flap) inFlap[static_cast<std::size_t>(i)] = true;
            double rest = 0.0;
            for (std::size_t i = 0; i < x.size(); ++i)
                if (!inFlap[i]) rest += x[i].y() / double(x.size() - flap.size());
            double lowest = 0.0, highest = 0.0;
            for (Index i : flap) {
                lowest = std::min(lowest, x[static_cast<std::size_t>(i)].y() - rest);
                highest = std::max(highest, x[static_cast<std::size_t>(i)].y() - rest);
            }
            qInfo("%s%s: flap between %.3f and %.3f m of the rest's mean height %.3f m",
                  mountain ? "mountain" : "valley", fromBelow ? " seen from below" : "", lowest,
                  highest, rest);
            if (mountain != fromBelow) {
                QVERIFY(lowest < -0.1);
                QVERIFY(highest < 0.01);
            } else {
                QVERIFY(highest > 0.1);
                QVERIFY(lowest > -0.01);
            }
        }
    }

    void aMountainFoldOnTheDeskLiftsThePaperAndFoldsTheFlapUnder() {
        EditSession s = editorSession();
        QCOMPARE(s.fold(acrossTheMiddle(kPi, true)), FoldRefusal::None);
        // Lifted first (the flap and the rest of the sheet), then turned, then put down.
        const auto& groups = s.world().script.pins;
        QCOMPARE(groups.size(), std::size_t(2 + kCarrySegments + 2));
        const std::vector<Index> flap = groups[0].vertices, rest = groups[1].vertices;
        auto meanHeight = [&](const std::vector<Index>& vs) {
            double sum = 0.0;
            for (Index i : vs) sum += s.world().sheet.verts.x[i].y();
            return sum / double(vs.size());
        };
        advanceSeconds(s, kFoldLiftSeconds);
        const double lifted = std::min(meanHeight(flap), meanHeight(rest));
        const double took = kFoldLiftSeconds + runUntilLetGo(s);
        const double flapPut = meanHeight(flap), restPut = meanHeight(rest);
        advanceSeconds(s, 2.0);
        const double angle = foldAngle(s.world().sheet, length());
        qInfo("mountain fold on the desk: lifted %.3f m, let go after %.2f s with the flap at "
              "%.4f m under the rest at %.4f m; 2 s later %.1f deg, flap at %.4f m, rest at %.4f m",
              lifted, took, flapPut, restPut, angle, meanHeight(flap), meanHeight(rest));
        QVERIFY(flapPut < restPut);
        QVERIFY(lifted > 0.1); // clear of the desk for the flap to pass under
        QVERIFY(std::abs(took - (2 * kFoldLiftSeconds + kPi / kFoldTurnRate + kFoldPress)) < 0.02);
        QVERIFY(angle > 170.0);
        // Nothing keeps the layers apart (no self-contact): stiff paper's crease holds the
        // rest on the flap; the paper's soft crease (`jacobi`, the machinery of the
        // sanitizer builds) lets the rest sink through the flap within 0.25 s.
        if (s.world().params.integrator != "jacobi") QVERIFY(meanHeight(flap) < meanHeight(rest));
        for (const Vec3& x : s.world().sheet.verts.x) QVERIFY(x.y() < 0.03); // back down
    }

    void aSecondFoldAcrossTheFirstTurnsInThePapersPlane_data() {
        QTest::addColumn<QString>("integrator");
        QTest::newRow("jacobi") << QStringLiteral("jacobi");
        // xpbd's projection overshot on the slivers the first fold's breaks left: 515 %.
        QTest::newRow("xpbd") << QStringLiteral("xpbd");
    }

    void aSecondFoldAcrossTheFirstTurnsInThePapersPlane() {
        // Where the paper lies folded, its layers face opposite ways: the fold must still
        // turn about a line in the paper's plane, or the flap is swung through the rest
        // (the mean of the normals did that: springs stretched to 976 %).
        QFETCH(QString, integrator);
        // xpbd's row is a number the Release build checks (CI time under the sanitizers).
        if (PAPERFOLD_TEST_SLOWDOWN > 1 && integrator == QLatin1String("xpbd"))
            QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(true, integrator.toStdString());
        QCOMPARE(s.fold({Vec3(-0.2, 0, 0.12), Vec3(0.2, 0, -0.02), kPi, false}), FoldRefusal::None);
        runUntilLetGo(s);
        advanceSeconds(s, 2.0);
        QCOMPARE(s.fold({Vec3(0.01, 0, -0.2), Vec3(0.0, 0, 0.2), kPi, true}), FoldRefusal::None);
        double worst = 0.0;
        while (s.folding()) {
            QCOMPARE(s.advance(12), StepStatus::Ok);
            worst = std::max(worst, computeStats(s.world().sheet).maxStretch);
        }
        qInfo("largest stretch while the second fold was carried: %.1f %%", 100.0 * worst);
        // Paper that does not stretch: what is left is where the first crease meets the
        // new line, in the steps a break makes new edges across a sheared cell
        // (docs/model.md). The paper's soft springs stretch as they always do.
        QVERIFY(worst < (integrator == QLatin1String("xpbd") ? 0.05 : 1.0));
    }

    void aSecondFoldAcrossTheFirstStays() {
        // The sheet folded in two and folded again across the first crease: a doubled
        // stack, whose fold spreads over two or three rows of the mesh. It sprang open
        // (the sheet's width back to 0.19-0.21 m) while a crease's springback was a whole
        // row's; and the lift, counting the first fold's open loop as paper to clear,
        // carried the flap round in a loose roll that stretched its band 5.85 %.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        struct SecondFold {
            const char* name;
            double line;
            bool mountain;
        };
        const SecondFold folds[] = {{"valley through the middle", 0.0, false},
                                    {"valley 2 cm off the middle", 0.02, false},
                                    {"mountain 1 cm off the middle", 0.01, true}};
        double apartSum = 0.0;
        for (const SecondFold& f : folds) {
            EditSession s = editorSession(true, "xpbd");
            QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
            runUntilLetGo(s);
            advanceSeconds(s, 1.0);
            QCOMPARE(s.fold({Vec3(f.line, 0, -0.2), Vec3(f.line, 0, 0.2), kPi, f.mountain}),
                     FoldRefusal::None);
            QVERIFY(runUntilLetGo(s) > 0.0);
            advanceSeconds(s, 2.0);
            const double stretch = computeStats(s.world().sheet).maxStretch;
            const double turnedApart = layersTurnedApart(s.world().sheet);
            const Vec3 lay = centreOfMass(s.world().sheet);
            advanceSeconds(s, 4.0);
            double left = 1e9, right = -1e9;
            for (const Vec3& x : s.world().sheet.verts.x) {
                left = std::min(left, x.x());
                right = std::max(right, x.x());
            }
            qInfo("%s: 2 s after the let-go the largest stretch is %.2f %% and the layers "
                  "lie %.1f degrees apart; 6 s after, the sheet is %.3f m wide (0.21 m "
                  "unfolded, 0.105 m folded flat)",
                  f.name, 100.0 * stretch, turnedApart, right - left);
            // Issue 9's bound, on the slivers the breaks inserted too.
            QVERIFY2(stretch < 0.01, f.name);
            QVERIFY2(right - left < 0.16, f.name);
            // And it lies still. It never slept, and crept across the desk at 0.6-4 mm/s
            // for as long as it was left: a cycle between the sub-steps and the
            // projection that the desk's friction turned into a walk (sim/DeskHold.h).
            const double crept = (centreOfMass(s.world().sheet) - lay).norm();
            QVERIFY2(
                crept < 2e-4,
                qPrintable(
                    QStringLiteral("%1: crept %2 m in 4 s").arg(QLatin1String(f.name)).arg(crept)));
            QVERIFY2(s.simulation().asleep(), f.name);
            QVERIFY2(turnedApart < 12.0, f.name);
            apartSum += turnedApart;
        }
        // Its four layers lie one on another, as a hand lays them. With the rest of the
        // sheet free while the flap went round, the carry dragged it round and the layers
        // ended 14.9, 16.3 and 7.4 degrees apart in these three folds (mean 12.9;
        // sim/FoldPlan.cpp). Held, one fold's angle is chaotic: changing an unrelated
        // constant (kProjectionCompliance) by 10 % moved single folds between 1.1 and
        // 9.6 degrees, while the three folds' mean stayed within 3.7-6.1 (docs/speed.md).
        const double apartMean = apartSum / static_cast<double>(std::size(folds));
        qInfo("the three folds' layers lie %.1f degrees apart on average", apartMean);
        QVERIFY(apartMean < 9.0);
    }

    void aFoldedCardStaysWhereItLies_data() {
        QTest::addColumn<double>("line");
        QTest::newRow("once, across the middle") << 1.0;
        QTest::newRow("twice, through the middle") << 0.0;
        QTest::newRow("twice, 2 cm off the middle") << 0.02;
    }

    void aFoldedCardStaysWhereItLies() {
        // A user's card folded across the middle slid 2.5 m in about 90 s with no input;
        // folded twice, a card walked up to 17 mm/s headless.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        QFETCH(double, line);
        World w = makeEditorScene("press", SceneOptions{}, 0.03);
        w.params.integrator = "xpbd";
        QVERIFY(materialPreset("card", w.params.material));
        EditSession s(std::move(w));
        QCOMPARE(s.advance(120), StepStatus::Ok);
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        runUntilLetGo(s);
        if (line < 1.0) {
            advanceSeconds(s, 1.0);
            QCOMPARE(s.fold({Vec3(line, 0, -0.2), Vec3(line, 0, 0.2), kPi, false}),
                     FoldRefusal::None);
            QVERIFY(runUntilLetGo(s) > 0.0);
        }
        advanceSeconds(s, 1.0);
        const Vec3 lay = centreOfMass(s.world().sheet);
        advanceSeconds(s, 4.0);
        const double crept = (centreOfMass(s.world().sheet) - lay).norm();
        qInfo("1-5 s after the let-go it crept %.3g mm; asleep: %d", 1e3 * crept,
              int(s.simulation().asleep()));
        QVERIFY(crept < 2e-4);
        QVERIFY(s.simulation().asleep());
    }

    void pinnedPaperStaysAndTheOtherSideIsFolded() {
        // A user pinned paper near the middle and drew a valley fold past the pins: the
        // lighter side, the flap, had pins in it, was carried away from them and tore
        // (25.8 % stretch, 608 breaks, then 489 breaks a second). The pinned side stays
        // and the other is folded over it; with pins on both sides nothing can be.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(true, "xpbd");
        const auto& V = s.world().sheet.verts;
        QVERIFY(s.pin(Vec3(0.0, 0.0, 0.12), 0.005));
        Index pinned = kNone;
        for (Index i = 0; i < V.size(); ++i)
            if (V.pinned[i]) pinned = i;
        QVERIFY(pinned != kNone);
        const Vec3 held = V.x[pinned];
        // The line across the middle, drawn from the other end: the same line.
        QCOMPARE(s.fold({Vec3(0.15, 0.0, 0.0), Vec3(-0.15, 0.0, 0.0), kPi, false}),
                 FoldRefusal::None);
        double worst = 0.0;
        while (s.folding()) {
            QCOMPARE(s.advance(1), StepStatus::Ok);
            worst = std::max(worst, computeStats(s.world().sheet).maxStretch);
        }
        advanceSeconds(s, 2.0);
        const Index breaksAfter = computeStats(s.world().sheet).breaks;
        advanceSeconds(s, 1.0);
        double nearest = 1e9;
        for (const Vec3& x : V.x) nearest = std::min(nearest, x.z());
        qInfo("worst stretch while carried %.2f %%; the sheet reaches z = %.3f m (-0.149 "
              "unfolded); %ld breaks 2 s after the let-go, %ld a second later; the pin moved "
              "%.2g m",
              100.0 * worst, nearest, static_cast<long>(breaksAfter),
              static_cast<long>(computeStats(s.world().sheet).breaks), (V.x[pinned] - held).norm());
        QVERIFY(V.pinned[pinned]);
        QVERIFY(nearest > -0.02); // the unpinned half lies folded over the pinned one
        QVERIFY(worst < 0.05);
        QCOMPARE(computeStats(s.world().sheet).breaks, breaksAfter); // settled
        // Pins on both sides of a line: refused, and nothing moves.
        Index other = 0;
        for (Index i = 0; i < V.size(); ++i)
            if ((V.x[i] - Vec3(0.06, 0.0, 0.06)).squaredNorm() <
                (V.x[other] - Vec3(0.06, 0.0, 0.06)).squaredNorm())
                other = i;
        QVERIFY(s.pin(V.x[other], 0.002));
        const std::size_t scripted = s.world().script.pins.size();
        QCOMPARE(s.fold({Vec3(0.03, 0.0, -0.2), Vec3(0.03, 0.0, 0.2), kPi, false}),
                 FoldRefusal::PinnedBothSides);
        QVERIFY(!s.folding());
        QCOMPARE(s.world().script.pins.size(), scripted); // no carry planned
    }

    void theCarriedFlapIsNotMarkedAsPinned() {
        // The carry holds the flap by a hand that lets go; a user could not tell its red
        // crosses from the pins they had set. Pins stay pins.
        EditSession s = editorSession();
        QVERIFY(s.pin(s.world().sheet.verts.x[0], 0.005));
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        QCOMPARE(s.advance(10), StepStatus::Ok);
        const SheetSnapshot during = makeSnapshot(s.simulation());
        QCOMPARE(during.pinned, std::vector<Index>{0});
        QVERIFY(during.held.size() > 100);
        runUntilLetGo(s);
        const SheetSnapshot after = makeSnapshot(s.simulation());
        QCOMPARE(after.pinned, std::vector<Index>{0});
        QVERIFY(after.held.empty());
    }

    void whatCannotBeFoldedIsRefusedWithItsReason() {
        EditSession s = editorSession();
        // The paper faces up on the desk, and a pin holds it down: a mountain fold would
        // carry the flap through the desk, and the sheet cannot be lifted over it.
        const Vec3 corner = s.world().sheet.verts.x[0];
        const auto pinned = s.pin(corner, 0.005);
        QVERIFY(pinned);
        QCOMPARE(s.fold(acrossTheMiddle(kPi, true)), FoldRefusal::DeskInTheWay);
        QVERIFY(s.undoStroke(pinned->stroke));
        QCOMPARE(s.fold({Vec3(0, 0, 0), Vec3(0.005, 0, 0), kPi, false}), FoldRefusal::ShortLine);
        QCOMPARE(s.fold({Vec3(-0.15, 0, 0.5), Vec3(0.15, 0, 0.5), kPi, false}),
                 FoldRefusal::OffSheet);
        // Along the edge: nothing lies beyond it.
        QCOMPARE(s.fold({Vec3(-0.15, 0, 0.1485), Vec3(0.15, 0, 0.1485), kPi, false}),
                 FoldRefusal::NothingToFold);
        QCOMPARE(s.fold(acrossTheMiddle(0.0)), FoldRefusal::BadAngle);
        QCOMPARE(s.fold(acrossTheMiddle(std::nan(""))), FoldRefusal::BadAngle);
        QVERIFY(!s.folding());
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        // One edit at a time while the flap is carried.
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::Busy);
        QVERIFY(!s.undoStroke(0));
        QVERIFY(!s.pin(s.world().sheet.verts.x[0], 0.01));
        s.grab(s.world().sheet.verts.x[0], true, true);
        QVERIFY(!s.grabbing());
        QVERIFY(!s.setTool(Vec3(0, 0.02, 0), 0.03, true, true));
        s.setTool(Vec3(0, 0.02, 0), 0.03, true, false);
        QVERIFY(s.folding());
    }

    void undoGivesBackTheFlatSheetAndRedoTheFold() {
        EditSession s = editorSession();
        const std::vector<Vec3> before = s.world().sheet.verts.x;
        const Index vertices = s.world().sheet.verts.size();
        s.fold(acrossTheMiddle());
        runUntilLetGo(s);
        const auto ended = s.takeFinished();
        QVERIFY(ended);
        const std::vector<Vec3> after = s.world().sheet.verts.x;
        const std::uint64_t folded = stateHash(s.world().sheet);
        QVERIFY(s.world().sheet.verts.size() > vertices);

        QCOMPARE(s.undoStroke(ended->stroke).value_or(-1), ended->events);
        QCOMPARE(s.world().sheet.verts.size(), vertices);
        QVERIFY(s.world().sheet.verts.x == before);
        QVERIFY(foldAngle(s.world().sheet, length()) < 5.0);
        for (std::uint8_t p : s.world().sheet.verts.pinned) QCOMPARE(p, std::uint8_t(0));

        QCOMPARE(s.redoStroke(ended->stroke).value_or(-1), ended->events);
        QVERIFY(s.world().sheet.verts.x == after);
        QCOMPARE(stateHash(s.world().sheet), folded);
    }

    void theWatchReadsHowFarTheFlapTurnedBack() {
        // A flat flap of four vertices, watched, then turned rigidly about a line of its
        // own: the watch reads the turn against the carry's axis (x), once, a second on.
        Sheet sheet;
        for (const Vec2& X : {Vec2(0.0, 0.0), Vec2(0.1, 0.0), Vec2(0.0, 0.1), Vec2(0.1, 0.1)})
            sheet.addVertex(Vec3(X.x(), 0.01, X.y()), Vec3::Zero(), 1e-3, X);
        const std::vector<Index> flap{0, 1, 2, 3};
        const std::vector<Vec3> letGo = sheet.verts.x;
        const auto turnBy = [&](double degrees, const Vec3& shift) {
            const Eigen::AngleAxisd turn(degrees * kPi / 180.0, Vec3::UnitX());
            for (Index i : flap)
                sheet.verts.x[i] = turn * (letGo[i] - Vec3(0.0, 0.01, 0.0)) + shift;
        };
        struct Case {
            double turn;
            Vec3 shift;
            double folded; // degrees
            double back;
        };
        // Turned back is against the carry: a turn about +x carried it on. A flat fold
        // that opens a little past flat reads past a half turn, not as closing on.
        for (const Case& c :
             {Case{-60.0, Vec3::Zero(), 180.0, 60.0}, Case{30.0, Vec3::Zero(), 90.0, -30.0},
              Case{0.0, Vec3(0.02, 0.0, -0.03), 180.0, 0.0},
              Case{-150.0, Vec3::UnitY(), 180.0, 150.0}, Case{-185.0, Vec3::Zero(), 180.0, 185.0},
              Case{-185.0, Vec3::Zero(), 90.0, -175.0}}) {
            FoldWatch watch;
            watch.start(sheet, flap, Vec3::UnitX(), c.folded * kPi / 180.0, 2.0);
            turnBy(c.turn, c.shift);
            QVERIFY(!watch.check(sheet, 2.0 + 0.5 * FoldWatch::kSeconds));
            const auto reading = watch.check(sheet, 2.0 + FoldWatch::kSeconds);
            QVERIFY(reading && reading->turnedBack);
            const double back = *reading->turnedBack;
            QVERIFY2(std::abs(back - c.back) < 1e-9, qPrintable(QString::number(back)));
            QCOMPARE(reading->unfoldedShare, 0.0); // nothing was left out
            QVERIFY(!watch.check(sheet, 10.0));    // read once
            sheet.verts.x = letGo;
        }
        FoldWatch cancelled;
        cancelled.start(sheet, flap, Vec3::UnitX(), kPi, 0.0);
        cancelled.cancel();
        QVERIFY(!cancelled.check(sheet, 5.0));
        // A flap that is one row of vertices along the line has no width to read a turn
        // by: nothing is said rather than a guess.
        FoldWatch row;
        row.start(sheet, {0, 1}, Vec3::UnitX(), kPi, 0.0);
        turnBy(-120.0, Vec3::Zero());
        QVERIFY(!row.check(sheet, 5.0));
    }

    void theWatchReadsTheFlapAgainstTheRestOfTheSheet() {
        // A fold is the angle between the flap and the rest: in an editor session a stack
        // fell open as its lower part turned over under the flap, while the status bar
        // said "Folded." (the flap itself had hardly turned). A square of 4 vertices on the
        // desk and a flap of 4 carried over it by a half turn about the x axis.
        Sheet sheet;
        const std::vector<Vec2> square{Vec2(0.0, 0.02), Vec2(0.1, 0.02), Vec2(0.0, 0.1),
                                       Vec2(0.1, 0.1)};
        const Eigen::AngleAxisd halfTurn(kPi, Vec3::UnitX());
        for (const Vec2& X : square) // the flap, over the rest
            sheet.addVertex(halfTurn * Vec3(X.x(), -0.002, X.y()), Vec3::Zero(), 1e-3, X);
        for (const Vec2& X : square) // the rest, on the desk
            sheet.addVertex(Vec3(X.x(), 0.0, -X.y()), Vec3::Zero(), 1e-3, Vec2(X.x(), -X.y()));
        const std::vector<Index> flap{0, 1, 2, 3}, rest{4, 5, 6, 7};
        const std::vector<Vec3> letGo = sheet.verts.x;
        const auto turnedBackAfter = [&](double flapDegrees, double restDegrees) {
            const Eigen::AngleAxisd turnFlap(flapDegrees * kPi / 180.0, Vec3::UnitX());
            const Eigen::AngleAxisd turnRest(restDegrees * kPi / 180.0, Vec3::UnitX());
            sheet.verts.x = letGo;
            FoldWatch watch;
            watch.start(sheet, flap, Vec3::UnitX(), kPi, 1.0);
            for (Index i : flap) sheet.verts.x[i] = turnFlap * letGo[i] + Vec3(0.0, 0.3, 0.0);
            for (Index i : rest) sheet.verts.x[i] = turnRest * letGo[i] + Vec3(0.0, 0.3, 0.0);
            const auto reading = watch.check(sheet, 1.0 + FoldWatch::kSeconds);
            return reading && reading->turnedBack ? *reading->turnedBack : -999.0;
        };
        // Rolled over as a whole, a quarter turn either way: folded as it was.
        QVERIFY(std::abs(turnedBackAfter(-90.0, -90.0)) < 1e-9);
        QVERIFY(std::abs(turnedBackAfter(90.0, 90.0)) < 1e-9);
        // The rest turned over under the still flap: the sheet lies open.
        const double open = turnedBackAfter(0.0, 180.0);
        QVERIFY2(std::abs(open - 180.0) < 1e-9, qPrintable(QString::number(open)));
        QVERIFY(EditSession::foldNotice(open, std::nullopt, 180.0));
        // The flap opened a third of the way while the rest rolled a quarter turn on.
        const double third = turnedBackAfter(30.0, 90.0);
        QVERIFY2(std::abs(third - 60.0) < 1e-9, qPrintable(QString::number(third)));
    }

    void theWatchSaysWhatTheCarryLeftBehind() {
        // Of a stack folded twice, a third fold across it carried the upper layers over
        // and left the lower ones lying flat (the carry holds only paper that lies in the
        // plane along the line), while the status bar said "Folded.". A flap of four
        // vertices carried half a turn about the x axis through the origin, and two
        // layers of four it left out, 5 mm under it: one lying where it was, one that
        // went round with the flap.
        Sheet sheet;
        const std::vector<Vec2> square{Vec2(0.0, 0.02), Vec2(0.1, 0.02), Vec2(0.0, 0.1),
                                       Vec2(0.1, 0.1)};
        for (double height : {0.0, -0.005, -0.010})
            for (const Vec2& X : square)
                sheet.addVertex(Vec3(X.x(), height, X.y()), Vec3::Zero(), 1e-3, X);
        const std::vector<Index> flap{0, 1, 2, 3}, lower{4, 5, 6, 7}, lowest{8, 9, 10, 11};
        const std::vector<Vec3> atStart = sheet.verts.x;
        const Eigen::AngleAxisd halfTurn(kPi, Vec3::UnitX());
        const auto carry = [&](const std::vector<Index>& vertices) {
            for (Index i : vertices) sheet.verts.x[i] = halfTurn * atStart[i];
        };
        const auto leftOut = [&](std::vector<Index> vertices) {
            FoldWatch::LeftOut out;
            for (Index i : vertices) out.atStart.push_back(atStart[i]);
            out.vertices = std::move(vertices);
            return out;
        };
        carry(flap);
        // The lower layer went round, the lowest stayed: the half of the paper watched
        // (4 of 8 vertices) that was left out did not fold; the flap itself held.
        carry(lower);
        FoldWatch watch;
        std::vector<Index> both = lower; // both layers left out
        both.insert(both.end(), lowest.begin(), lowest.end());
        watch.start(sheet, flap, Vec3::UnitX(), kPi, 1.0, leftOut(lowest));
        auto reading = watch.check(sheet, 1.0 + FoldWatch::kSeconds);
        QVERIFY(reading && reading->turnedBack);
        QVERIFY(std::abs(*reading->turnedBack) < 1e-9);
        QVERIFY2(std::abs(reading->unfoldedShare - 0.5) < 1e-12,
                 qPrintable(QString::number(reading->unfoldedShare)));
        // Both layers left out, turned about the axis by `turn` since the fold (to
        // `folded`) began: what stayed, or 0 where they followed.
        const auto unfoldedAfter = [&](double turn, double folded) {
            for (Index i : both)
                sheet.verts.x[i] = Eigen::AngleAxisd(turn, Vec3::UnitX()) * atStart[i];
            FoldWatch w;
            w.start(sheet, flap, Vec3::UnitX(), folded, 1.0, leftOut(both));
            const auto r = w.check(sheet, 1.0 + FoldWatch::kSeconds);
            return r ? r->unfoldedShare : -1.0;
        };
        // Read vertex by vertex: the lower layer gone round, the lowest not, is the
        // lowest's 4 of 12.
        {
            carry(lower);
            FoldWatch w;
            w.start(sheet, flap, Vec3::UnitX(), kPi, 1.0, leftOut(both));
            const auto r = w.check(sheet, 1.0 + FoldWatch::kSeconds);
            QVERIFY(r);
            QVERIFY2(std::abs(r->unfoldedShare - 4.0 / 12.0) < 1e-12,
                     qPrintable(QString::number(r->unfoldedShare)));
        }
        // Gone round with the flap, or over half of its half turn: nothing to say. Nor
        // for a fold to 90°, whose carry took the flap round by a half turn first (the
        // paper it left out may stay there).
        QCOMPARE(unfoldedAfter(kPi, kPi), 0.0);
        QCOMPARE(unfoldedAfter(0.6 * kPi, kPi), 0.0);
        QCOMPARE(unfoldedAfter(kPi, 0.5 * kPi), 0.0);
        QCOMPARE(unfoldedAfter(0.3 * kPi, 0.5 * kPi), 0.0);
        // A lower layer that started under the line's plane ends more than a half turn
        // round: folded, not turned back.
        QCOMPARE(unfoldedAfter(1.2 * kPi, kPi), 0.0);
        // A third of the way to a fold to 90°, or the other way (against the carry), it
        // did not follow: 8 of 12 vertices.
        QVERIFY(std::abs(unfoldedAfter(kPi / 6, 0.5 * kPi) - 8.0 / 12.0) < 1e-12);
        QVERIFY(std::abs(unfoldedAfter(-kPi / 3, 0.5 * kPi) - 8.0 / 12.0) < 1e-12);
        // Each vertex is read about the line itself: the same layers folded about a line
        // 5 cm off, the lower carried round, read with that line's point (nothing lies
        // unfolded) and with a point 20 cm off it, about which the carried layer seems
        // to have turned by a few degrees only.
        const Vec3 off(0.0, 0.0, -0.05);
        for (Index i : flap) sheet.verts.x[i] = halfTurn * atStart[i] + off;
        for (Index i : lower) sheet.verts.x[i] = halfTurn * atStart[i] + off;
        for (Index i : lowest) sheet.verts.x[i] = atStart[i] + off;
        const auto readAbout = [&](const Vec3& pivot) {
            FoldWatch::LeftOut out;
            out.vertices = lower;
            for (Index i : lower) out.atStart.push_back(atStart[i] + off);
            out.pivot = pivot;
            FoldWatch w;
            w.start(sheet, flap, Vec3::UnitX(), kPi, 1.0, out);
            const auto r = w.check(sheet, 1.0 + FoldWatch::kSeconds);
            return r ? r->unfoldedShare : -1.0;
        };
        QCOMPARE(readAbout(off), 0.0);
        QCOMPARE(readAbout(Vec3(0.0, 0.0, 0.15)), 0.5);
    }

    void theSessionSaysWhetherTheFoldKeptItsCrease() {
        // The status bar said "the crease keeps it" at every let-go, also for a third
        // fold along the diagonal of a sheet folded twice, which sprang back 99°. Now
        // the session reads the flap a second after the let-go.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(true, "xpbd");
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        runUntilLetGo(s);
        std::optional<double> back;
        int steps = 0;
        for (; steps < 480 && !back; ++steps) {
            QCOMPARE(s.advance(1), StepStatus::Ok);
            back = s.takeFoldTurnedBack();
        }
        QVERIFY(back);
        qInfo("a fold across the middle turned back %.1f degrees in the %d steps after its "
              "let-go",
              *back, steps);
        QVERIFY(std::abs(steps / 240.0 - FoldWatch::kSeconds) < 0.01);
        QVERIFY(std::abs(*back) < 10.0);  // held: it closed a few degrees further
        QVERIFY(!s.takeFoldTurnedBack()); // said once
        QVERIFY(!s.takeFoldLeftBehind()); // a flat sheet's fold leaves nothing out
        // Undone before its second is up, nothing is said of it.
        QCOMPARE(s.fold({Vec3(0.0, 0.0, -0.2), Vec3(0.0, 0.0, 0.2), kPi, false}),
                 FoldRefusal::None);
        runUntilLetGo(s);
        const auto second = s.takeFinished();
        QVERIFY(second);
        QVERIFY(s.undoStroke(second->stroke));
        saysNothingOfTheFoldFor(s, 480);
        // Nor after a Reset within it: the flat new sheet is no fold that opened.
        QCOMPARE(s.fold({Vec3(0.0, 0.0, -0.2), Vec3(0.0, 0.0, 0.2), kPi, false}),
                 FoldRefusal::None);
        runUntilLetGo(s);
        QCOMPARE(s.advance(120), StepStatus::Ok);
        QVERIFY(s.reset(makeEditorScene("press", SceneOptions{}, 0.03)));
        saysNothingOfTheFoldFor(s, 480);
    }

    void aFoldThatFallsOpenIsSaidAsItOpens() {
        // Office paper folded to 60° falls open under the half sheet's weight: it is said
        // at the step its flap passes kSprangBack (a 90° fold lay flat while "Folded."
        // stood for most of the second), and the reading a second after the let-go says
        // how far it went. A fold that holds says neither.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(true, "xpbd");
        QCOMPARE(s.fold(acrossTheMiddle(kPi / 3)), FoldRefusal::None);
        runUntilLetGo(s);
        int opening = -1, read = -1;
        std::optional<double> back;
        for (int step = 1; step <= 480 && read < 0; ++step) {
            QCOMPARE(s.advance(1), StepStatus::Ok);
            if (s.takeFoldOpening()) {
                QCOMPARE(opening, -1); // once
                opening = step;
            }
            if ((back = s.takeFoldTurnedBack())) read = step;
        }
        qInfo("a 60 degree fold was said to open %d steps after its let-go, and read %.0f "
              "degrees back after %d",
              opening, back ? *back : 0.0, read);
        QVERIFY(opening > 0 && read > 0);
        QVERIFY(opening < read);
        QVERIFY(back && *back > EditSession::kSprangBack);
        QVERIFY(!s.takeFoldOpening());
        // A flat fold across the middle holds: nothing is said while it is watched.
        EditSession held = editorSession(true, "xpbd");
        QCOMPARE(held.fold(acrossTheMiddle()), FoldRefusal::None);
        runUntilLetGo(held);
        for (int step = 0; step < 480; ++step) {
            QCOMPARE(held.advance(1), StepStatus::Ok);
            QVERIFY(!held.takeFoldOpening());
        }
    }

    void aCreaseKeepsTheAngleItWasOpenedTo() {
        // Office paper folded flat, opened back to an angle and let go keeps about that
        // angle: what springs back is the elastic part of the crease. Gravity is switched
        // off at the let-go, so that the flap's weight, which this crease cannot hold up
        // (docs/model.md), does not decide. The plate's sum stencils used to read a fold
        // at half its curvature, stayed elastic across it and pulled it back toward
        // flat: 135° and 90° lay at 65° and 64° after 2 s.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        for (const double asked : {135.0, 90.0, 60.0}) {
            EditSession s = editorSession(true, "xpbd");
            QCOMPARE(s.fold(acrossTheMiddle(asked * kPi / 180.0)), FoldRefusal::None);
            runUntilLetGo(s);
            SimParams weightless = s.world().params;
            weightless.gravity = 0.0;
            s.setParams(weightless);
            advanceSeconds(s, 2.0);
            const double kept = foldAngle(s.world().sheet, length());
            qInfo("folded to %.0f degrees, it lies at %.1f degrees 2 s after the let-go", asked,
                  kept);
            QCOMPARE_GE(kept, asked - 5.0);
            QCOMPARE_LE(kept, asked + 30.0);
        }
    }

    void aFoldThatFallsShutIsSaid() {
        // The editor's sheet folded to 90° falls flat onto the rest once let go (its
        // crease cannot hold the flap up); the status bar said "Folded.".
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(true, "xpbd");
        QCOMPARE(s.fold(acrossTheMiddle(kPi / 2)), FoldRefusal::None);
        runUntilLetGo(s);
        std::optional<double> back;
        for (int step = 0; step < 480 && !back; ++step) {
            QCOMPARE(s.advance(1), StepStatus::Ok);
            QVERIFY(!s.takeFoldOpening()); // it closes, it does not open
            back = s.takeFoldTurnedBack();
        }
        QVERIFY(back);
        qInfo("a 90 degree fold turned back %.1f degrees a second after its let-go, at %.0f "
              "degrees",
              *back, foldAngle(s.world().sheet, length()));
        QCOMPARE(s.foldAskedDegrees(), 90.0);
        const auto notice = EditSession::foldNotice(back, s.takeFoldLeftBehind(), 90.0);
        QVERIFY(notice && notice->kind == EditSession::FoldNotice::Kind::FellShut);
        QCOMPARE(notice->value, 90.0); // the angle it could not hold
        QVERIFY(foldAngle(s.world().sheet, length()) > 150.0);
    }

    void aFoldThatOpenedIsSaidBeforeWhatItLeftBehind() {
        using Kind = EditSession::FoldNotice::Kind;
        const auto notice = EditSession::foldNotice;
        QVERIFY(!notice(std::nullopt, std::nullopt, 180.0));
        QVERIFY(!notice(-3.0, std::nullopt, 180.0)); // held, nothing left out
        QVERIFY(!notice(EditSession::kSprangBack, 0.5 * EditSession::kLeftBehindShare, 180.0));
        auto n = notice(120.0, 0.4, 180.0); // opened, and what it left behind with it
        QVERIFY(n && n->kind == Kind::SprangBack && n->value == 120.0);
        // A flap cannot open more than it was folded: a 60° fold read 61° back.
        n = notice(61.0, std::nullopt, 60.0);
        QVERIFY(n && n->kind == Kind::SprangBack && n->value == 60.0);
        n = notice(30.0, EditSession::kLeftBehindShare, 180.0); // held, a tenth left lying
        QVERIFY(n && n->kind == Kind::LeftPaperBehind && n->value == EditSession::kLeftBehindShare);
        n = notice(std::nullopt, 0.3, 180.0); // a flap too narrow to read, paper left lying
        QVERIFY(n && n->kind == Kind::LeftPaperBehind && n->value == 0.3);
        // Closed well past the angle asked, to within kShutWithin of flat (a 90° fold fell
        // flat, read 94° on): it fell shut, from the angle asked, said before what it left
        // behind; a flat fold that closes a few degrees on is not said.
        n = notice(-94.0, 0.5, 90.0);
        QVERIFY(n && n->kind == Kind::FellShut && n->value == 90.0);
        n = notice(-(180.0 - EditSession::kShutWithin - 90.0), std::nullopt, 90.0);
        QVERIFY(n && n->kind == Kind::FellShut);
        QVERIFY(!notice(-EditSession::kSprangBack, std::nullopt, 180.0));
        // Closed far, but not shut (card folded to 60° stood at 124°): how far it closed.
        n = notice(-64.0, std::nullopt, 60.0);
        QVERIFY(n && n->kind == Kind::ClosedFurther && n->value == 64.0);
    }

    void theSessionSaysWhenTheFoldLeftPaperBehind() {
        // The editor's sheet folded across the middle, then across that, then across the
        // quarter, 2 s after each let-go as a user waits. The carry holds only the paper
        // lying in the plane along the line, so the third fold leaves layers of the stack
        // out; whether they go round with the flap is the physics' (a run that waited 1 s
        // instead of 2 took them round), so what is checked is that the session says it
        // when they lie unfolded, checked against which side of the line each lies on (the
        // two agree but for paper near the vertical through the line), that the folds
        // before, whose left-out paper went round, say nothing, and that an undo within
        // the second does not either.
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        EditSession s = editorSession(true, "xpbd");
        const auto& V = s.world().sheet.verts;
        std::optional<double> turned, left;
        const auto foldAndWait = [&](const FoldRequest& request) {
            QCOMPARE(s.fold(request), FoldRefusal::None);
            runUntilLetGo(s);
            turned.reset();
            left.reset();
            for (int k = 0; k < 480; ++k) {
                QCOMPARE(s.advance(1), StepStatus::Ok);
                if (const auto t = s.takeFoldTurnedBack()) turned = t;
                if (const auto l = s.takeFoldLeftBehind()) left = l;
            }
        };
        QVERIFY(planFold(s.world(), acrossTheMiddle()).leftOut.vertices.empty()); // a flat sheet
        foldAndWait(acrossTheMiddle());
        QVERIFY(turned && !left);
        const FoldRequest second{Vec3(0.0, 0.0, -0.2), Vec3(0.0, 0.0, 0.2), kPi, false};
        QVERIFY(!planFold(s.world(), second).leftOut.vertices.empty()); // the first fold's loop
        foldAndWait(second);
        QVERIFY(turned && *turned < EditSession::kSprangBack);
        QVERIFY2(!left || *left < EditSession::kLeftBehindShare,
                 "the second fold took the first one's loop round");

        Vec3 lo = V.x[0], hi = V.x[0];
        for (const Vec3& x : V.x) {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
        const double z = 0.5 * (lo.z() + hi.z());
        const FoldRequest third{Vec3(lo.x() - 0.02, 0.0, z), Vec3(hi.x() + 0.02, 0.0, z), kPi,
                                false};
        const FoldPlan plan = planFold(s.world(), third);
        QCOMPARE(plan.refusal, FoldRefusal::None);
        std::size_t carried = 0;
        for (const PinGroup& g : plan.motions)
            if (g.turnRate != 0.0) carried = g.vertices.size();
        qInfo("the third fold carries %zu vertices and leaves %zu out", carried,
              plan.leftOut.vertices.size());
        QVERIFY(plan.leftOut.vertices.size() > carried / 4); // the stack's other layers
        // Undone within its second, the third fold says nothing, though it left paper out.
        QCOMPARE(s.fold(third), FoldRefusal::None);
        runUntilLetGo(s);
        const auto undone = s.takeFinished();
        QVERIFY(undone);
        QVERIFY(s.undoStroke(undone->stroke));
        saysNothingOfTheFoldFor(s, 480);
        // Still on the flap's side of the line: each left-out vertex by itself.
        std::vector<double> sideBefore;
        for (Index i : plan.leftOut.vertices) sideBefore.push_back(V.x[i].z() - z);
        foldAndWait(third);
        std::size_t stillThere = 0;
        for (std::size_t k = 0; k < plan.leftOut.vertices.size(); ++k)
            if (sideBefore[k] * (V.x[plan.leftOut.vertices[k]].z() - z) > 0.0) ++stillThere;
        const double share = double(stillThere) / double(plan.leftOut.vertices.size() + carried);
        qInfo("%zu of its left-out vertices are still on the flap's side (%.2f of that side); "
              "turned back %.1f degrees; the session says %s",
              stillThere, share, turned ? *turned : 0.0,
              left ? qPrintable(QString::number(*left)) : "nothing");
        QVERIFY(turned);
        // The watch reads each vertex's turn about the line, this its side of it: the two
        // agree but for paper near the vertical through the line.
        if (left)
            QVERIFY(std::abs(*left - share) < 0.1);
        else
            QVERIFY(share < EditSession::kLeftBehindShare + 0.1);
    }

    void undoAllAndRedoAllGivesBackEveryFold() {
        // Where the sheet breaks settling after a fold, the next fold began on that mesh,
        // so redoing the first must give it back, or the second cannot be redone. (Since
        // creases soften, these folds no longer break after the let-go: 503 and 544
        // vertices at the let-go and 2 s later; the hashes below still hold Redo to the
        // sheet as it was.)
        EditSession s = editorSession();
        std::vector<EditSession::StrokeEnd> folds;
        for (const FoldRequest& r :
             {acrossTheMiddle(), FoldRequest{Vec3(0.01, 0, -0.2), Vec3(0.0, 0, 0.2), kPi, true}}) {
            QCOMPARE(s.fold(r), FoldRefusal::None);
            runUntilLetGo(s);
            folds.push_back(*s.takeFinished());
            advanceSeconds(s, 2.0);
        }
        // Redo gives back the sheet as the user saw it when undoing the last fold.
        const std::uint64_t twice = stateHash(s.world().sheet);
        const Index vertices = s.world().sheet.verts.size();
        // As in the editor, which plays on between the clicks.
        QVERIFY(s.undoStroke(folds[1].stroke));
        advanceSeconds(s, 1.0);
        QVERIFY(s.undoStroke(folds[0].stroke));
        advanceSeconds(s, 1.0);
        QCOMPARE(s.world().sheet.verts.size(), Index(494)); // the fresh 19 x 26 sheet
        QVERIFY(s.redoStroke(folds[0].stroke));
        advanceSeconds(s, 1.0); // it breaks a little more, settling again
        const auto second = s.redoStroke(folds[1].stroke);
        QVERIFY(second && *second > 0);
        QCOMPARE(s.world().sheet.verts.size(), vertices);
        QCOMPARE(stateHash(s.world().sheet), twice);
    }

    void aStepThatBlowsUpDuringAFoldLetsTheFlapGo() {
        // The explicit integrator at the editor's frame step blows up under the carry:
        // the fold ends (the flap free, the groups gone, an undo step), and the session
        // is the user's again; it replays the same way.
        World w = makeEditorScene("press", SceneOptions{}, 0.03);
        w.params.integrator = "symplectic";
        w.params.dt = 1.0 / 60.0;
        EditSession s(std::move(w));
        QCOMPARE(s.fold(acrossTheMiddle()), FoldRefusal::None);
        int k = 0;
        while (s.advance(1) == StepStatus::Ok && k < 600) ++k;
        QVERIFY2(k < 600, "symplectic Euler at h = 1/60 must diverge under the carry");
        QVERIFY(!s.folding());
        QVERIFY(s.world().script.pins.empty());
        for (std::uint8_t p : s.world().sheet.verts.pinned) QCOMPARE(p, std::uint8_t(0));
        const auto ended = s.takeFinished();
        QVERIFY(ended);
        QCOMPARE(ended->kind, EditSession::StrokeKind::Fold);
        QVERIFY(s.undoStroke(ended->stroke)); // not refused as "busy"
        const RecordingLoad load = decodeRecording(encodeRecording(s.log()));
        QVERIFY2(load.log, qPrintable(load.error));
        EditSession again(*load.log);
        QCOMPARE(replay(*load.log, again), std::string());
        QVERIFY(encodeWorld(again.world()) == encodeWorld(s.world()));
    }

    void aSheetOpenedMidFoldIsAFoldUnderWay() {
        // Opened in the editor (replaceWorld), a sheet saved mid-fold goes on folding as
        // the session's own fold: other edits wait, and it ends as an undo step.
        EditSession s = editorSession();
        s.fold(acrossTheMiddle());
        advanceSeconds(s, 1.0);
        const WorldLoad load = decodeWorld(encodeWorld(s.worldToSave()));
        QVERIFY2(load.world, qPrintable(load.error));
        EditSession opened = editorSession();
        opened.replaceWorld(*load.world);
        QVERIFY(opened.folding());
        QVERIFY(!opened.pin(opened.world().sheet.verts.x[0], 0.01));
        runUntilLetGo(opened);
        const auto ended = opened.takeFinished();
        QVERIFY(ended);
        QCOMPARE(ended->kind, EditSession::StrokeKind::Fold);
        QVERIFY(opened.world().script.pins.empty());
        QVERIFY(foldAngle(opened.world().sheet, length()) > 170.0);
    }

    void aFoldReplaysBitForBitFromItsRecording() {
        EditSession s = editorSession();
        FoldRequest mountain = acrossTheMiddle(kPi / 2, true);
        mountain.viewer = Vec3(0.0, 0.8, 0.6); // seen from in front, above
        QCOMPARE(s.fold(mountain), FoldRefusal::None);
        runUntilLetGo(s);
        advanceSeconds(s, 1.0);
        const auto ended = s.takeFinished();
        QVERIFY(ended);
        s.undoStroke(ended->stroke);
        advanceSeconds(s, 0.2);
        s.redoStroke(ended->stroke);
        advanceSeconds(s, 0.5);
        // Through the file: the fold's line, angle and kind survive it.
        const RecordingLoad load = decodeRecording(encodeRecording(s.log()));
        QVERIFY2(load.log, qPrintable(load.error));
        int folds = 0;
        for (const EditCommand& c : load.log->commands) {
            if (c.kind != EditCommand::Kind::Fold) continue;
            ++folds;
            QVERIFY(c.fold);
            QCOMPARE(c.fold->angle, kPi / 2);
            QVERIFY(c.fold->mountain);
            QVERIFY(c.fold->from == acrossTheMiddle().from);
            QVERIFY(c.fold->to == acrossTheMiddle().to);
            QVERIFY(c.fold->viewer == Vec3(0.0, 0.8, 0.6));
        }
        QCOMPARE(folds, 1);
        EditSession again(*load.log);
        QCOMPARE(replay(*load.log, again), std::string());
        QCOMPARE(stateHash(again.world().sheet), stateHash(s.world().sheet));
    }

    void aSheetSavedMidFoldFinishesTheFold() {
        EditSession s = editorSession();
        s.fold(acrossTheMiddle(kPi / 2));
        advanceSeconds(s, 2.0); // round, pressed, not yet opened
        const WorldLoad load = decodeWorld(encodeWorld(s.worldToSave()));
        QVERIFY2(load.world, qPrintable(load.error));
        // The carry, in kCarrySegments turns, the opening by half a turn, in half as many,
        // and the rest held.
        QCOMPARE(load.world->script.pins.size(),
                 std::size_t(kCarrySegments + kCarrySegments / 2 + 1));
        Simulation resumed(*load.world);
        runUntilLetGo(s);
        advanceSeconds(s, 0.5);
        while (resumed.world().stepCount < s.world().stepCount)
            QCOMPARE(resumed.step(), StepStatus::Ok);
        QCOMPARE(stateHash(resumed.world().sheet), stateHash(s.world().sheet));
    }
};

QTEST_GUILESS_MAIN(TestFoldTool)
#include "test_fold_tool.moc"
