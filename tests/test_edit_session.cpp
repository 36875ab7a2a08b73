// The editing layer in sim/: the tool's speed limit, strokes and their undo and redo
// through §4.2 recovery, driven headless exactly as the editor's simulation thread does.
#include "EditSession.h"
#include "SceneScript.h"
#include "Scenes.h"
#include "SheetValidation.h"

#include <QtTest>
#include <random>

using namespace pf;

namespace {

struct Topology {
    Index vertices, springs, triangles, activeEvents;
    bool operator==(const Topology&) const = default;
};

Topology topology(const Sheet& s) {
    Index active = 0;
    for (const DamageEvent& e : s.events) active += e.active ? 1 : 0;
    return {s.verts.size(), s.springs.size(), s.triangleCount(), active};
}

// One stroke along the press scene's scripted path (down onto the sheet, across it,
// up again), as the editor's mouse would drive it: one target per 1/60 s frame.
std::optional<EditSession::StrokeEnd> pushStroke(EditSession& session, double from, double to) {
    const std::vector<SphereKey> path = makeScene("press")->script.sphereKeys;
    const double radius = session.world().sphere.radius;
    const int stepsPerFrame =
        std::max(1, int(std::lround((1.0 / 60.0) / session.world().params.dt)));
    session.setTool(spherePathAt(path, from), radius, true, false);
    session.placeToolAtTarget();
    session.setTool(spherePathAt(path, from), radius, true, true);
    for (double t = from; t < to; t += 1.0 / 60.0) {
        session.setTool(spherePathAt(path, t), radius, true, true);
        if (session.advance(stepsPerFrame) != StepStatus::Ok) return std::nullopt;
    }
    return session.setTool(spherePathAt(path, to), radius, true, false);
}

} // namespace

class TestEditSession : public QObject {
    Q_OBJECT

  private slots:
    void theToolNeverOutrunsItsSpeedLimit() {
        World w = *makeScene("press");
        w.sheet = Sheet(); // the tool alone
        EditSession session(w);
        const Vec3 start = session.world().sphere.center;
        const Vec3 target = start + Vec3(1.0, 0.0, 0.0);
        session.setTool(target, 0.02, true, false);
        const double dt = session.world().params.dt;
        QCOMPARE(session.advance(10), StepStatus::Ok);
        const double moved = (session.world().sphere.center - start).norm();
        QVERIFY(std::abs(moved - 10 * EditSession::kMaxToolSpeed * dt) < 1e-12);
        QVERIFY(std::abs(session.world().sphere.velocity.norm() - EditSession::kMaxToolSpeed) <
                1e-9);
        // Given time, it arrives and stops there.
        QCOMPARE(session.advance(int(std::ceil(1.0 / (EditSession::kMaxToolSpeed * dt))) + 1),
                 StepStatus::Ok);
        QCOMPARE(session.world().sphere.center, target);
        QCOMPARE(session.world().sphere.velocity, Vec3::Zero());
    }

    void pausedTheToolJumpsToItsTargetWithoutAStep() {
        EditSession session(*makeScene("press"));
        const auto step = session.world().stepCount;
        const Vec3 target = session.world().sphere.center + Vec3(0.3, 0.0, 0.0);
        session.setTool(target, 0.02, true, false);
        QVERIFY(session.placeToolAtTarget());
        QCOMPARE(session.world().sphere.center, target);
        QVERIFY(!session.placeToolAtTarget()); // already there
        QCOMPARE(session.world().stepCount, step);
    }

    void aStrokeWithoutDamageHasNothingToUndo() {
        World w = *makeScene("press");
        w.params.breaking = false;
        w.params.hinges = false;
        EditSession session(w);
        QVERIFY(!pushStroke(session, 0.0, 0.6).has_value());
        QVERIFY(!session.undoStroke(0).has_value());
        QVERIFY(!session.redoStroke(-1).has_value());
    }

    void undoAndRedoOfStrokesInAnyOrderKeepAValidMesh() {
        EditSession session(*makeScene("press"));
        const Topology before = topology(session.world().sheet);
        std::vector<EditSession::StrokeEnd> strokes;
        std::vector<Topology> after;
        for (const auto& [from, to] : {std::pair{0.0, 0.5}, {0.5, 0.9}, {0.9, 1.3}}) {
            const auto end = pushStroke(session, from, to);
            QVERIFY2(end.has_value(), "each stroke along the press path breaks the sheet");
            QVERIFY(end->events > 0);
            QCOMPARE(end->stroke, int(strokes.size()));
            strokes.push_back(*end);
            after.push_back(topology(session.world().sheet));
        }
        // Undone newest first, each stroke gives back every event it made, and the mesh
        // returns to what it was before that stroke.
        for (int k = 2; k >= 0; --k) {
            QCOMPARE(session.undoStroke(k), std::optional<int>(strokes[k].events));
            QCOMPARE(topology(session.world().sheet), k == 0 ? before : after[k - 1]);
            QCOMPARE(QString::fromStdString(validateSheet(session.world().sheet)), QString());
        }
        // Redone oldest first, each gives back the stroke's mesh.
        for (int k = 0; k <= 2; ++k) {
            QCOMPARE(session.redoStroke(k), std::optional<int>(strokes[k].events));
            QCOMPARE(topology(session.world().sheet), after[k]);
        }
        // Any order, stepping in between: never an invalid mesh.
        std::mt19937 rng(7);
        std::vector<bool> done(3, true);
        for (int round = 0; round < 60; ++round) {
            const int k = int(rng() % 3);
            const auto n = done[k] ? session.undoStroke(k) : session.redoStroke(k);
            QVERIFY(n.has_value());
            QVERIFY(*n >= 0 && *n <= strokes[k].events);
            done[k] = !done[k];
            QCOMPARE(session.advance(2), StepStatus::Ok);
            QCOMPARE(QString::fromStdString(validateSheet(session.world().sheet)), QString());
        }
    }

    void aNewSheetForgetsTheStrokesButKeepsTheTool() {
        EditSession session(*makeScene("press"));
        QVERIFY(pushStroke(session, 0.0, 0.5).has_value());
        const double radius = 0.031;
        session.setTool(session.world().sphere.center, radius, true, false);
        session.replaceWorld(*makeScene("drape"));
        QVERIFY(!session.undoStroke(0).has_value());
        QCOMPARE(session.world().sphere.radius, radius);
        QVERIFY(session.world().sphere.active);
        QVERIFY(session.world().script.sphereKeys.empty());
    }
};

QTEST_GUILESS_MAIN(TestEditSession)
#include "test_edit_session.moc"
