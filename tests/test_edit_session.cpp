// The editing layer in sim/: the tool's speed limit, strokes and their undo and redo
// through §4.2 recovery, driven headless exactly as the editor's simulation thread does.
#include "Breaking.h"
#include "EditSession.h"
#include "JacobiScene.h"
#include "Normals.h"
#include "RecordingFile.h"
#include "SceneScript.h"
#include "Scenes.h"
#include "SheetFile.h"
#include "SheetSnapshot.h"
#include "SheetStats.h"
#include "SheetValidation.h"
#include "XpbdIntegrator.h"

#include <QTest>
#include <QtEndian>
#include <limits>
#include <numbers>
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

// The sheet as it was seen: the same mesh and every vertex where it was, bit for bit.
#define QCOMPARE_SHEET(now, seen)                                                                  \
    do {                                                                                           \
        QCOMPARE(topology(now), topology(seen));                                                   \
        QVERIFY((now).verts.x == (seen).verts.x);                                                  \
    } while (false)

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

// A push straight down onto `point` from 5 cm above it, pressed 1 cm below it, a quarter
// second down and let go.
std::optional<EditSession::StrokeEnd> pressInto(EditSession& session, const Vec3& point) {
    const double radius = session.world().sphere.radius;
    const Vec3 above = point + Vec3(0.0, radius + 0.05, 0.0);
    session.setTool(above, radius, true, false);
    session.placeToolAtTarget();
    session.setTool(above, radius, true, true);
    session.setTool(point + Vec3(0.0, radius - 0.01, 0.0), radius, true, true);
    if (session.advance(60) != StepStatus::Ok) return std::nullopt;
    return session.setTool(point + Vec3(0.0, radius - 0.01, 0.0), radius, true, false);
}

// Two strokes along the press path, a quarter second apart, both breaking the sheet.
std::optional<std::pair<EditSession::StrokeEnd, EditSession::StrokeEnd>>
pushTwice(EditSession& session) {
    const auto first = pushStroke(session, 0.0, 0.6);
    session.advance(60);
    const auto second = pushStroke(session, 0.6, 1.0);
    if (!first || first->events == 0 || !second || second->events == 0) return std::nullopt;
    return std::pair{*first, *second};
}

// Damage the sheet makes as it settles, as the editor plays on: the first edge that can
// break, broken by hand.
void breakAsItSettles(EditSession& session) {
    Sheet& s = session.simulation().world().sheet;
    Index edge = 0;
    while (!canBreak(s, edge)) ++edge;
    std::vector<Vec3> normals;
    computeVertexNormals(s, normals);
    breakEdge(s, edge, normals, 0.25, session.world().stepCount);
}

// A session that uses every command: two strokes, an undo and a redo, a change of φ,
// the tool placed while paused, and stepping in between.
void scriptedSession(EditSession& session) {
    pushStroke(session, 0.0, 0.5);
    session.advance(30);
    SimParams p = session.world().params;
    p.phi = 0.4;
    session.setParams(p);
    pushStroke(session, 0.5, 0.9);
    session.undoStroke(1);
    session.advance(12);
    session.redoStroke(1);
    session.undoStroke(0);
    session.setTool(Vec3(0.05, 0.1, 0.02), 0.03, true, false);
    session.placeToolAtTarget();
    session.advance(20);
}

QString hex(std::uint64_t h) {
    return QStringLiteral("%1").arg(h, 16, 16, QLatin1Char('0'));
}

// The encoded recording with bytes of its first command changed.
QByteArray withCommandBytes(const EditLog& log, qsizetype offset, const QByteArray& value) {
    QByteArray bytes = encodeRecording(log);
    // The "commands" key, then the byte string's CBOR head: major type 2 with the length
    // inline or in the next 1, 2 or 4 bytes.
    qsizetype at = bytes.indexOf(QByteArray("\x68"
                                            "commands")) +
                   9;
    const int lengthBytes[] = {0, 1, 2, 4};
    const int info = bytes[at] & 0x1f;
    at += 1 + (info < 24 ? 0 : lengthBytes[info - 23]);
    bytes.replace(at + offset, value.size(), value);
    return bytes;
}

QByteArray withCommandByte(const EditLog& log, qsizetype offset, char value) {
    return withCommandBytes(log, offset, QByteArray(1, value));
}

// The session's recording replays to the same world, in memory and through the file.
void checkReplays(const EditSession& session) {
    EditSession replayed(session.log());
    QCOMPARE(QString::fromStdString(replay(session.log(), replayed)), QString());
    QCOMPARE(encodeWorld(replayed.world()), encodeWorld(session.world()));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("session.paperrec"));
    QString error;
    QVERIFY2(saveRecording(session.log(), path, &error), qPrintable(error));
    const RecordingLoad load = loadRecording(path);
    QVERIFY2(load.log, qPrintable(load.error));
    EditSession fromFile(*load.log);
    QCOMPARE(QString::fromStdString(replay(*load.log, fromFile)), QString());
    QCOMPARE(stateHash(fromFile.world().sheet), stateHash(session.world().sheet));
}

} // namespace

class TestEditSession : public QObject {
    Q_OBJECT

  private slots:
    void theToolNeverOutrunsItsSpeedLimit() {
        World w = test::machineryScene("press");
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
        EditSession session(test::machineryScene("press"));
        const auto step = session.world().stepCount;
        const Vec3 target = session.world().sphere.center + Vec3(0.3, 0.0, 0.0);
        session.setTool(target, 0.02, true, false);
        QVERIFY(session.placeToolAtTarget());
        QCOMPARE(session.world().sphere.center, target);
        QVERIFY(!session.placeToolAtTarget()); // already there
        QCOMPARE(session.world().stepCount, step);
    }

    void aHoveringToolTouchesNothing() {
        // A user moved the mouse over the sheet in three zigzags with no button pressed
        // (tissue, the tool at 4.4 cm): the sphere, touching the paper where the cursor
        // met it and sweeping through it between targets, broke it 728 times and threw
        // it off the view, with nothing to undo. Hovering shows the tool and leaves the
        // paper alone; pressed, the same tool pushes it.
        World w = makeEditorScene("press", SceneOptions{}, 0.044);
        QVERIFY(materialPreset("tissue", w.params.material));
        EditSession session(w);
        QCOMPARE(session.advance(120), StepStatus::Ok); // settled on the desk
        const Sheet before = session.world().sheet;
        const double radius = 0.044;
        const int stepsPerFrame =
            std::max(1, int(std::lround((1.0 / 60.0) / session.world().params.dt)));
        // Where the cursor's ray meets the flat sheet, the tool's centre is one radius
        // above it (render/Picking: toolCenter with no depth).
        for (int zig = 0; zig < 3; ++zig)
            for (int i = 0; i <= 25; ++i) {
                const double x = -0.1 + 0.2 * i / 25.0 * (zig % 2 == 0 ? 1.0 : -1.0) +
                                 (zig % 2 == 0 ? 0.0 : 0.2);
                const double z = -0.12 + 0.12 * zig + 0.004 * i;
                session.setTool(Vec3(x, radius, z), radius, true, false);
                QCOMPARE(session.advance(stepsPerFrame), StepStatus::Ok);
                QVERIFY(session.world().sphere.hovering);
                QVERIFY(!session.world().sphere.active);
            }
        const Sheet& after = session.world().sheet;
        QCOMPARE(topology(after), topology(before));
        double moved = 0.0;
        for (Index i = 0; i < after.verts.size(); ++i)
            moved = std::max(moved, (after.verts.x[i] - before.verts.x[i]).norm());
        qInfo("hovered 78 frames: the paper moved %.2e m at most", moved);
        QVERIFY2(moved < 1e-6, qPrintable(QStringLiteral("moved %1 m").arg(moved)));
        QVERIFY(!session.undoStroke(0).has_value()); // nothing was done

        // The button pressed where the tool hovers: it goes down from there and pushes.
        const Vec3 at(0.0, radius, 0.0);
        session.setTool(at, radius, true, false);
        QCOMPARE(session.advance(60), StepStatus::Ok);
        const Vec3 hovered = session.world().sphere.center;
        const Vec3 pressed = at - Vec3(0.0, 0.6 * radius, 0.0);
        session.setTool(pressed, radius, true, true);
        QVERIFY(session.world().sphere.active);
        QCOMPARE(session.world().sphere.center, hovered); // no jump into the paper
        for (int frame = 0; frame < 15; ++frame) {
            session.setTool(pressed + Vec3(0.004 * frame, 0.0, 0.0), radius, true, true);
            QCOMPARE(session.advance(stepsPerFrame), StepStatus::Ok);
        }
        const auto end = session.setTool(pressed + Vec3(0.06, 0.0, 0.0), radius, true, false);
        QVERIFY(end.has_value()); // the push changed the sheet: one undo step
        double pushed = 0.0;
        for (Index i = 0; i < before.verts.size(); ++i)
            pushed =
                std::max(pushed, (session.world().sheet.verts.x[i] - before.verts.x[i]).norm());
        QVERIFY2(pushed > 1e-3, qPrintable(QStringLiteral("pushed %1 m").arg(pushed)));
    }

    // A tool that starts pushing from a place into the desk (a hover goes where it is
    // asked and touches nothing) is lifted onto the desk without being given that lift as
    // its velocity: taken as 4.4 m/s upward, its grip flung the sheet at 3.5 m/s and broke
    // 158 springs in the first frame. Pressed and moved at 0.25 m/s, it drags the sheet
    // along the desk no faster than it moves.
    void aToolPressedFromIntoTheDeskDoesNotFlingThePaper() {
        World w = makeEditorScene("press", SceneOptions{}, 0.03);
        EditSession session(w);
        QCOMPARE(session.advance(60), StepStatus::Ok);
        const double radius = 0.03;
        const int stepsPerFrame =
            std::max(1, int(std::lround((1.0 / 60.0) / session.world().params.dt)));
        Vec3 at(0.08, 0.4 * radius, -0.03); // 60 % of the radius into the paper on the desk
        session.setTool(at, radius, true, false);
        session.placeToolAtTarget();
        const auto& V = session.world().sheet.verts;
        double fastest = 0.0;
        for (int frame = 0; frame < 10; ++frame) {
            at += Vec3(-0.25 / 60.0, 0.0, 0.0);
            session.setTool(at, radius, true, true);
            QCOMPARE(session.advance(stepsPerFrame), StepStatus::Ok);
            QVERIFY(session.world().sphere.active);
            QVERIFY2(session.world().sphere.velocity.y() < 0.01,
                     qPrintable(QString::number(session.world().sphere.velocity.y())));
            Vec3 momentum = Vec3::Zero();
            double mass = 0.0;
            for (Index i = 0; i < V.size(); ++i) {
                momentum += V.m[i] * V.v[i];
                mass += V.m[i];
            }
            fastest = std::max(fastest, momentum.norm() / mass);
        }
        qInfo("the sheet's centre of mass at most %.3f m/s (the tool 0.25 m/s)", fastest);
        QVERIFY(fastest < 0.3);
        QCOMPARE(computeStats(session.world().sheet).breaks, 0);
    }

    void aStrokeThatChangedNothingHasNothingToUndo() {
        // The button held with the tool 10 cm above the sheet: nothing to give back.
        EditSession session(test::machineryScene("press"));
        const Vec3 above(0.0, 0.1, 0.0);
        session.setTool(above, 0.02, true, false);
        session.placeToolAtTarget();
        session.setTool(above, 0.02, true, true);
        QCOMPARE(session.advance(20), StepStatus::Ok);
        QVERIFY(!session.setTool(above + Vec3(0.01, 0.0, 0.0), 0.02, true, false).has_value());
        QVERIFY(!session.undoStroke(0).has_value());
        QVERIFY(!session.redoStroke(-1).has_value());
    }

    void undoGivesBackTheSheetAsItWasBeforeTheStroke() {
        // With breaking off the push only moves the paper: still one undo step, and undo
        // puts every vertex back where it was when the button went down.
        World w = test::machineryScene("press");
        w.params.breaking = false;
        w.params.hinges = false;
        EditSession session(w);
        QCOMPARE(session.advance(24), StepStatus::Ok);
        const std::vector<Vec3> before = session.world().sheet.verts.x;
        const auto end = pushStroke(session, 0.0, 0.6);
        QVERIFY(end.has_value());
        QCOMPARE(end->events, 0);
        const std::vector<Vec3> after = session.world().sheet.verts.x;
        QCOMPARE(session.advance(60), StepStatus::Ok); // the paper settles meanwhile
        const std::vector<Vec3> seen = session.world().sheet.verts.x;
        QVERIFY(seen != after);
        QCOMPARE(session.undoStroke(end->stroke), std::optional<int>(0));
        QVERIFY(session.world().sheet.verts.x == before);
        // Redo: the sheet as it was when the user undid the stroke.
        QCOMPARE(session.redoStroke(end->stroke), std::optional<int>(0));
        QVERIFY(session.world().sheet.verts.x == seen);
    }

    void onlyTheNewestStrokesKeepTheirSheetStates() {
        // Each stroke here lifts vertex 0 by 1 mm (as a push would move it).
        World w = test::machineryScene("press");
        EditSession session(w);
        const Vec3 above(0.0, 0.2, 0.0);
        const int count = int(EditSession::kStrokesWithLook) + 1;
        for (int k = 0; k < count; ++k) {
            session.setTool(above, 0.02, true, true);
            session.simulation().world().sheet.verts.x[0].y() += 0.001;
            QVERIFY(session.setTool(above, 0.02, true, false).has_value());
        }
        const double top = session.world().sheet.verts.x[0].y();
        // The newest gives its sheet back; the oldest, beyond the limit, only its damage.
        session.undoStroke(count - 1);
        QCOMPARE(session.world().sheet.verts.x[0].y(), top - 0.001);
        session.undoStroke(0);
        QCOMPARE(session.world().sheet.verts.x[0].y(), top - 0.001);
        session.undoStroke(1);
        QCOMPARE(session.world().sheet.verts.x[0].y(), w.sheet.verts.x[0].y() + 0.001);
    }

    void undoOfAStrokeThatBrokeTheSheetGivesBackItsLook() {
        EditSession session(test::jacobiScene("press"));
        QCOMPARE(session.advance(24), StepStatus::Ok);
        const Sheet before = session.world().sheet;
        const std::int64_t strokeStep = session.world().stepCount;
        const auto end = pushStroke(session, 0.0, 0.6);
        QVERIFY(end.has_value() && end->events > 0);
        const Topology left = topology(session.world().sheet);
        QCOMPARE(session.advance(60), StepStatus::Ok);
        // What the user sees when they undo: the stroke's sheet after a second of settling.
        const Sheet seen = session.world().sheet;
        // Its own breaks and those the sheet made settling afterwards.
        const auto recovered = session.undoStroke(end->stroke);
        QVERIFY(recovered.has_value() && *recovered >= end->events);
        const Sheet& undone = session.world().sheet;
        QCOMPARE_SHEET(undone, before);
        QVERIFY(undone.verts.v == before.verts.v);
        QVERIFY(undone.springs.rest == before.springs.rest);
        // Nor does the editor's break rate still count the breaks the undo took back.
        QVERIFY(breaksSince(seen, strokeStep) > 0);
        QCOMPARE(breaksSince(undone, strokeStep), 0);
        // Redo gives back what was seen before the undo, settling included.
        QCOMPARE(session.redoStroke(end->stroke), recovered);
        QCOMPARE_SHEET(session.world().sheet, seen);
        QVERIFY(session.world().sheet.verts.v == seen.verts.v);
        // Creases keep the length they broke at, so the fold holds when steps resume.
        QVERIFY(session.world().sheet.springs.rest == seen.springs.rest);
        // The breaks keep the steps they were made at, so the editor's break rate (the
        // breaks of the last second) does not read the redone ones as new: a user's fold
        // redone minutes after it was made read 78 breaks a second.
        const auto activeSteps = [](const Sheet& sheet) {
            std::vector<std::int64_t> steps;
            for (const DamageEvent& ev : sheet.events)
                if (ev.active) steps.push_back(ev.step);
            return steps;
        };
        QVERIFY(activeSteps(session.world().sheet) == activeSteps(seen));
        qInfo("the stroke left %d vertices, the user saw %d; undo recovered %d events",
              int(left.vertices), int(seen.verts.size()), *recovered);
    }

    void redoTakesBackWhatTheSheetBrokeSinceTheUndo() {
        // The editor plays on between an undo and a redo, and the sheet may break a
        // little as it settles: the redo takes that back and gives the stroke's sheet.
        EditSession session(test::jacobiScene("press"));
        const auto end = pushStroke(session, 0.0, 0.6);
        QVERIFY(end.has_value() && end->events > 0);
        const Topology after = topology(session.world().sheet);
        QVERIFY(session.undoStroke(end->stroke).has_value());
        breakAsItSettles(session);
        QCOMPARE(session.redoStroke(end->stroke), std::optional<int>(end->events));
        QCOMPARE(topology(session.world().sheet), after);
        QCOMPARE(QString::fromStdString(validateSheet(session.world().sheet)), QString());
    }

    // A user's session (tissue pinned at two corners, two pushes, then Undo, Undo, Redo,
    // Redo at 0.03x real time): the History said the second push was done again, but the
    // sheet was as the first had left it. The sheet broke as it settled between the two
    // undos; the first redo gave that damage back as its own, so the second push's mesh
    // never came back and its redo did nothing. Whatever the user does between the undos
    // and the redos that is no new undo step, the redos give back what was seen.
    void redosInOrderGiveBackWhatWasSeenAfterTheSheetBrokeBetween_data() {
        QTest::addColumn<int>("between");
        QTest::newRow("nothing") << 0;
        QTest::newRow("a press of the tool that moves nothing") << 1;
        QTest::newRow("a settle") << 2;
    }
    void redosInOrderGiveBackWhatWasSeenAfterTheSheetBrokeBetween() {
        QFETCH(int, between);
        EditSession session(test::jacobiScene("press"));
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        QCOMPARE(session.advance(30), StepStatus::Ok);
        const Sheet seen = session.world().sheet;
        QVERIFY(session.undoStroke(second.stroke).has_value());
        breakAsItSettles(session);
        if (between == 1) {
            const Vec3 high(0.0, 0.5, 0.0);
            session.setTool(high, 0.01, true, true);
            QVERIFY(!session.setTool(high, 0.01, true, false).has_value());
        } else if (between == 2) {
            session.settle(); // chosen, and undone before it froze
        }
        // What the user sees when choosing the second Undo, and gets back from the first
        // Redo (it once gave back the sheet as the first undo had left it, 30 s earlier).
        const Sheet seenAtTheSecondUndo = session.world().sheet;
        QVERIFY(session.undoStroke(first.stroke).has_value());
        QVERIFY(session.redoStroke(first.stroke).has_value());
        QCOMPARE_SHEET(session.world().sheet, seenAtTheSecondUndo);
        const auto redone = session.redoStroke(second.stroke);
        QVERIFY(redone.has_value());
        QVERIFY2(*redone > 0, "the second push's redo broke nothing");
        QCOMPARE_SHEET(session.world().sheet, seen);
        QCOMPARE(QString::fromStdString(validateSheet(session.world().sheet)), QString());
    }

    // Once the second push's redo has taken back what the first kept apart for it, the
    // first holds it no more: a second round of undos and redos, and one with a new push
    // in it, give back what was seen each time (a stale share gave it back unseen, and
    // refused the new push's redo).
    void aSecondRoundOfUndosAndRedosGivesBackWhatWasSeen() {
        EditSession session(test::jacobiScene("press"));
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        const auto undoBothAndRedoTheFirst = [&] {
            QVERIFY(session.undoStroke(second.stroke));
            breakAsItSettles(session);
            const Sheet seen = session.world().sheet;
            QVERIFY(session.undoStroke(first.stroke));
            QVERIFY(session.redoStroke(first.stroke));
            QCOMPARE_SHEET(session.world().sheet, seen);
        };
        for (int round = 0; round < 2; ++round) {
            const Sheet seen = session.world().sheet;
            undoBothAndRedoTheFirst();
            if (QTest::currentTestFailed()) return;
            QVERIFY(session.redoStroke(second.stroke));
            QCOMPARE_SHEET(session.world().sheet, seen);
        }
        // A new push drops the second's redo; it and the first undone, both come back.
        QVERIFY(session.undoStroke(second.stroke));
        breakAsItSettles(session);
        const auto third = pushStroke(session, 1.0, 1.3);
        QVERIFY(third);
        const Sheet seen = session.world().sheet;
        QVERIFY(session.undoStroke(third->stroke));
        QVERIFY(session.undoStroke(first.stroke));
        QVERIFY(session.redoStroke(first.stroke));
        QVERIFY(session.redoStroke(third->stroke));
        QCOMPARE_SHEET(session.world().sheet, seen);
        QCOMPARE(QString::fromStdString(validateSheet(session.world().sheet)), QString());
    }

    // Strokes made after a Reset, undone back past it and redone: each redo gives back
    // what was seen at its undo (a helper's session got a flat sheet from an earlier round).
    void strokesAfterAResetAreRedoneAsSeenAcrossItsUndoAndRedo() {
        EditSession session(test::jacobiScene("press"));
        QVERIFY(pushStroke(session, 0.0, 0.5));
        const auto reset = session.reset(test::jacobiScene("press"));
        QVERIFY(reset);
        QCOMPARE(session.advance(12), StepStatus::Ok);
        // Pinned at two corners, as the user's was.
        const auto& V = session.world().sheet.verts;
        Index a = 0, b = 0;
        for (Index i = 0; i < V.size(); ++i) {
            if (V.x[i].z() - V.x[i].x() > V.x[a].z() - V.x[a].x()) a = i;
            if (V.x[i].z() + V.x[i].x() > V.x[b].z() + V.x[b].x()) b = i;
        }
        const auto pinA = session.pin(V.x[a], 0.005);
        const auto pinB = session.pin(V.x[b], 0.005);
        QVERIFY(pinA && pinB);
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        for (int round = 0; round < 3; ++round) {
            QCOMPARE(session.advance(20), StepStatus::Ok);
            const Sheet atSecondUndo = session.world().sheet;
            QVERIFY(session.undoStroke(second.stroke));
            breakAsItSettles(session);
            const Sheet atFirstUndo = session.world().sheet;
            QVERIFY(session.undoStroke(first.stroke));
            if (round > 0) {
                QVERIFY(session.undoStroke(pinB->stroke));
                QVERIFY(session.undoStroke(pinA->stroke));
                QVERIFY(session.undoStroke(reset->stroke));
                QVERIFY(session.redoStroke(reset->stroke));
                QVERIFY(session.redoStroke(pinA->stroke));
                QVERIFY(session.redoStroke(pinB->stroke));
            }
            QVERIFY(session.redoStroke(first.stroke));
            QCOMPARE_SHEET(session.world().sheet, atFirstUndo);
            QVERIFY(session.redoStroke(second.stroke));
            QCOMPARE_SHEET(session.world().sheet, atSecondUndo);
        }
    }

    // A step's count of breaks and hinges is said again when it changes: a push takes
    // what the sheet broke settling after it once the next edit begins, keeps apart what
    // it broke after a later step's undo, and gives that back at the later step's redo.
    void aStepsBreaksAreCountedAgainWhenItTakesOrGivesBackDamage() {
        EditSession session(test::jacobiScene("press"));
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        const auto recounts = [&] {
            std::vector<std::pair<int, int>> out;
            for (const auto& r : session.takeRecounted()) out.emplace_back(r.stroke, r.events);
            return out;
        };
        recounts(); // whatever the two pushes took between them
        QVERIFY(session.undoStroke(second.stroke));
        breakAsItSettles(session);
        QVERIFY(session.undoStroke(first.stroke));
        const auto kept = recounts();
        QCOMPARE(kept.size(), std::size_t(1));
        QCOMPARE(kept[0].first, first.stroke);
        const int withDamage = kept[0].second;
        QVERIFY(session.redoStroke(first.stroke));
        QVERIFY(recounts().empty());
        QVERIFY(session.redoStroke(second.stroke)); // takes that damage back from the first
        const auto given = recounts();
        QCOMPARE(given.size(), std::size_t(1));
        QCOMPARE(given[0].first, first.stroke);
        QCOMPARE(given[0].second, withDamage - 1);
        // Settling damage after the newest push is said as the sheet makes it (the
        // History read the count of the let-go until the next edit).
        breakAsItSettles(session);
        QCOMPARE(session.advance(1), StepStatus::Ok);
        const auto settling = recounts();
        QCOMPARE(settling.size(), std::size_t(1));
        QCOMPARE(settling[0].first, second.stroke);
        QVERIFY(settling[0].second >= second.events + 1);
        QCOMPARE(session.advance(1), StepStatus::Ok);
        const auto more = recounts(); // said again only if the step broke more
        QVERIFY(more.empty() || more[0].second > settling[0].second);
        // And it is the push's own once the next edit begins: the count said last (the
        // press comes before any step).
        breakAsItSettles(session);
        QCOMPARE(session.advance(1), StepStatus::Ok);
        const int saidLast = recounts().at(0).second;
        pushStroke(session, 0.2, 0.3);
        const auto taken = recounts();
        QCOMPARE(taken.size(), std::size_t(1));
        QCOMPARE(taken[0].first, second.stroke);
        QCOMPARE(taken[0].second, saidLast);
        QVERIFY(recounts().empty()); // once
    }

    // The fresh sheet of a Reset may break before the first step made on it (a Reset to
    // `crumple-cycles`, whose pins gather the sheet at once). That damage is the Reset's:
    // its redo gives back the sheet the next step began on, so that step is redone too,
    // and a Reset undone as the newest step is redone as it was when undone.
    void aResetIsRedoneWithWhatItsSheetBrokeBeforeTheNextStep() {
        EditSession session(test::jacobiScene("press"));
        QVERIFY(pushStroke(session, 0.0, 0.5));
        const auto reset = session.reset(test::jacobiScene("press"));
        QVERIFY(reset);
        QCOMPARE(session.advance(12), StepStatus::Ok);
        breakAsItSettles(session);
        const Sheet atUndo = session.world().sheet;
        QVERIFY(session.undoStroke(reset->stroke));
        QVERIFY(session.redoStroke(reset->stroke));
        QCOMPARE_SHEET(session.world().sheet, atUndo);

        breakAsItSettles(session); // and again, before the first step on it
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        QCOMPARE(session.advance(20), StepStatus::Ok);
        const Sheet atSecondUndo = session.world().sheet;
        QVERIFY(session.undoStroke(second.stroke));
        QVERIFY(session.undoStroke(first.stroke));
        const Sheet atResetUndo = session.world().sheet;
        QVERIFY(session.undoStroke(reset->stroke));
        QVERIFY(session.redoStroke(reset->stroke));
        QCOMPARE(topology(session.world().sheet), topology(atResetUndo));
        QVERIFY(session.redoStroke(first.stroke));
        QVERIFY2(session.redoStroke(second.stroke), "the second push's redo was refused");
        QCOMPARE_SHEET(session.world().sheet, atSecondUndo);
    }

    // Undo and redo give back the scene's own motions where they stood with the sheet
    // they give back: crumple-cycles' rim, given back as it was at the undo while the
    // script went on from where the Reset's redo had put it, was pulled flat to 111-159 %
    // stretch (a helper's session).
    void undoAndRedoGiveBackWhereTheScenesMotionsStood() {
        EditSession session(test::jacobiScene("press"));
        const auto reset = session.reset(test::jacobiScene("crumple-cycles"));
        QVERIFY(reset);
        QCOMPARE(session.advance(240), StepStatus::Ok);
        // How far into its script the sheet is: the same for every group.
        const auto phase = [&] {
            return session.world().time - session.world().script.pins.front().start;
        };
        QVERIFY(!session.world().script.pins.empty());
        const double pressedAt = phase();
        const auto push = pushStroke(session, 0.0, 0.6);
        QVERIFY(push && push->events > 0);
        QCOMPARE(session.advance(192), StepStatus::Ok);
        const double undoneAt = phase();
        const Sheet seen = session.world().sheet;
        QVERIFY(session.undoStroke(push->stroke));
        QCOMPARE(phase(), pressedAt); // the sheet as pressed, and its motions as then
        QCOMPARE(session.advance(192), StepStatus::Ok);
        QVERIFY(session.undoStroke(reset->stroke));
        QCOMPARE(session.advance(192), StepStatus::Ok);
        QVERIFY(session.redoStroke(reset->stroke));
        QCOMPARE(phase(), pressedAt); // the sheet the push found
        QCOMPARE(session.advance(192), StepStatus::Ok);
        QVERIFY(session.redoStroke(push->stroke));
        QVERIFY(session.world().sheet.verts.x == seen.verts.x);
        QCOMPARE(phase(), undoneAt);
    }

    // An undo of a Reset while a grab holds its fresh sheet keeps that sheet for the redo
    // without the hand's pin (a held grab pins its vertex for the step): redone, the sheet
    // had a pin nobody set, and it was saved with it.
    void aResetUndoneDuringAGrabIsRedoneWithoutTheHandsPin() {
        EditSession session(test::jacobiScene("press"));
        const auto reset = session.reset(test::jacobiScene("press"));
        QVERIFY(reset);
        const auto pins = [&] {
            const auto& p = session.world().sheet.verts.pinned;
            return std::count(p.begin(), p.end(), 1);
        };
        QCOMPARE(pins(), 0);
        session.grab(session.world().sheet.verts.x[0], true, true);
        QVERIFY(session.grabbing());
        QCOMPARE(session.advance(4), StepStatus::Ok);
        QCOMPARE(pins(), 1); // the hand's
        QVERIFY(session.undoStroke(reset->stroke));
        QVERIFY(session.redoStroke(reset->stroke));
        QVERIFY(!session.grabbing());
        QCOMPARE(pins(), 0);
    }

    // The same with the sheet the user's was: a Reset to `crumple-cycles`, whose pins
    // gather the fresh sheet and break it before the first stroke on it, and go on
    // gathering it between the clicks of the undos and redos (a helper's session, playing,
    // 0.8 s apart: the pushes' redos moved the History and gave nothing back).
    void strokesOnAGatheredCrumpleCyclesSheetAreRedoneAfterItsResetIsUndoneAndRedone_data() {
        QTest::addColumn<int>("between");
        QTest::newRow("paused") << 0;
        QTest::newRow("playing, 0.8 s between clicks") << 192;
    }
    void strokesOnAGatheredCrumpleCyclesSheetAreRedoneAfterItsResetIsUndoneAndRedone() {
        QFETCH(int, between);
        const auto wait = [&](EditSession& s) { return s.advance(between) == StepStatus::Ok; };
        EditSession session(test::jacobiScene("press"));
        const auto reset = session.reset(test::jacobiScene("crumple-cycles"));
        QVERIFY(reset);
        const Index fresh = topology(session.world().sheet).activeEvents;
        QCOMPARE(session.advance(240), StepStatus::Ok);
        const Index gathered = topology(session.world().sheet).activeEvents;
        qInfo("the gather broke or hinged %d edges before the first stroke", int(gathered - fresh));
        QVERIFY(gathered > fresh);
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        QVERIFY(wait(session));
        const Sheet atSecondUndo = session.world().sheet;
        QVERIFY(session.undoStroke(second.stroke));
        QVERIFY(wait(session));
        QVERIFY(session.undoStroke(first.stroke));
        QVERIFY(wait(session));
        QVERIFY(session.undoStroke(reset->stroke));
        QVERIFY(wait(session));
        QVERIFY(session.redoStroke(reset->stroke));
        QVERIFY(wait(session));
        QVERIFY2(session.redoStroke(first.stroke), "the first push's redo was refused");
        QVERIFY(wait(session));
        QVERIFY2(session.redoStroke(second.stroke), "the second push's redo was refused");
        QCOMPARE_SHEET(session.world().sheet, atSecondUndo);

        // A push made after an undo, on the gathered sheet, while the undone push's redo
        // waited: redone after the Reset's undo and redo, on the mesh it began on.
        QVERIFY(session.undoStroke(second.stroke));
        QVERIFY(wait(session));
        const auto third = pushStroke(session, 0.6, 1.0);
        QVERIFY(third && third->events > 0);
        QVERIFY(wait(session));
        const Sheet atThirdUndo = session.world().sheet;
        QVERIFY(session.undoStroke(third->stroke));
        QVERIFY(session.undoStroke(first.stroke));
        QVERIFY(session.undoStroke(reset->stroke));
        QVERIFY(wait(session));
        QVERIFY(session.redoStroke(reset->stroke));
        QVERIFY(wait(session));
        QVERIFY2(session.redoStroke(first.stroke), "the first push's redo was refused");
        QVERIFY(wait(session));
        QVERIFY2(session.redoStroke(third->stroke), "the new push's redo was refused");
        QCOMPARE_SHEET(session.world().sheet, atThirdUndo);

        // And one made on the Reset's sheet while the first push's redo waited.
        QVERIFY(session.undoStroke(third->stroke));
        QVERIFY(session.undoStroke(first.stroke));
        QVERIFY(wait(session));
        const auto fourth = pushStroke(session, 0.0, 0.6);
        QVERIFY(fourth && fourth->events > 0);
        QVERIFY(wait(session));
        const Sheet atFourthUndo = session.world().sheet;
        QVERIFY(session.undoStroke(fourth->stroke));
        QVERIFY(session.undoStroke(reset->stroke));
        QVERIFY(wait(session));
        QVERIFY(session.redoStroke(reset->stroke));
        QVERIFY(wait(session));
        QVERIFY2(session.redoStroke(fourth->stroke), "the push after the undo was refused");
        QCOMPARE_SHEET(session.world().sheet, atFourthUndo);
    }

    // A redo while a push that broke the sheet is held is refused before it takes back
    // anything: the push's breaks would go with the damage since the undo.
    void aRedoWhileABreakingPushIsHeldIsRefused() {
        EditSession session(test::jacobiScene("press"));
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        QVERIFY(session.undoStroke(pushes->second.stroke));
        const std::vector<SphereKey> path = makeScene("press")->script.sphereKeys;
        const double radius = session.world().sphere.radius;
        session.setTool(spherePathAt(path, 1.0), radius, true, false);
        session.placeToolAtTarget();
        const Index before = topology(session.world().sheet).activeEvents;
        for (double t = 1.0; t < 1.3 && topology(session.world().sheet).activeEvents == before;
             t += 1.0 / 60.0) {
            session.setTool(spherePathAt(path, t), radius, true, true);
            QCOMPARE(session.advance(4), StepStatus::Ok);
        }
        const Topology held = topology(session.world().sheet);
        QVERIFY2(held.activeEvents > before, "the held push broke nothing");
        QCOMPARE(session.redoStroke(pushes->second.stroke), std::optional<int>());
        QCOMPARE(topology(session.world().sheet), held);
    }

    // The same damage between an undo and a new push: the push's redo, after an undo of the
    // push and of the stroke before it and a redo of that stroke, needs the mesh the push
    // began on, that damage included.
    void aStrokeMadeAfterAnUndoIsRedoneOnTheMeshItBeganOn() {
        EditSession session(test::jacobiScene("press"));
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        QVERIFY(session.undoStroke(second.stroke).has_value());
        breakAsItSettles(session);
        const auto third = pushStroke(session, 1.0, 1.3);
        QVERIFY(third.has_value());
        const Sheet seen = session.world().sheet;
        QVERIFY(session.undoStroke(third->stroke).has_value());
        QVERIFY(session.undoStroke(first.stroke).has_value());
        QVERIFY(session.redoStroke(first.stroke).has_value());
        QCOMPARE(session.redoStroke(third->stroke), std::optional<int>(third->events));
        QCOMPARE_SHEET(session.world().sheet, seen);
    }

    void redoIsRefusedOnAMeshAnotherStrokeChanged() {
        // Two strokes undone, the second redone first: its edge ids belong to the mesh
        // the first left, so it is refused and nothing breaks.
        EditSession session(test::jacobiScene("press"));
        const auto pushes = pushTwice(session);
        QVERIFY(pushes);
        const auto& [first, second] = *pushes;
        QVERIFY(session.undoStroke(second.stroke).has_value());
        QVERIFY(session.undoStroke(first.stroke).has_value());
        const Topology flat = topology(session.world().sheet);
        QCOMPARE(session.redoStroke(second.stroke), std::optional<int>());
        QCOMPARE(topology(session.world().sheet), flat);
        QCOMPARE(QString::fromStdString(validateSheet(session.world().sheet)), QString());
        // The refused step stays undone: its undo is refused too, and takes nothing of the
        // first stroke's, done again since (an undo after a refused redo once took the
        // damage of every step after where it began, 1,093 vertices down to 503).
        const auto redone = session.redoStroke(first.stroke);
        QVERIFY(redone && *redone >= first.events);
        const Topology firstDone = topology(session.world().sheet);
        QCOMPARE(session.undoStroke(second.stroke), std::optional<int>());
        QCOMPARE(topology(session.world().sheet), firstDone);
        // Nor is a step that is done done twice.
        QCOMPARE(session.redoStroke(first.stroke), std::optional<int>());
        QCOMPARE(topology(session.world().sheet), firstDone);
    }

    void undoAndRedoOfStrokesInAnyOrderKeepAValidMesh() {
        EditSession session(test::jacobiScene("press"));
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
            // A redo onto a mesh another stroke changed is refused, and the step stays
            // undone (its undo is refused in turn).
            const auto n = done[k] ? session.undoStroke(k) : session.redoStroke(k);
            QVERIFY(!n || *n >= 0);
            QVERIFY(n || !done[k]);
            if (n) done[k] = !done[k];
            QCOMPARE(session.advance(2), StepStatus::Ok);
            QCOMPARE(QString::fromStdString(validateSheet(session.world().sheet)), QString());
        }
    }

    // The overlay's Eq. 10 is the one the step drew, not worked out again per frame; an
    // edit between steps (new φ, undo) brings it up to date once.
    void theSnapshotsBreakProbabilitiesAreTheStepsAndFollowEdits() {
        EditSession session(test::jacobiScene("press"));
        pushStroke(session, 0.0, 0.6);
        auto fresh = [&] {
            BreakScratch scratch;
            computeBreakProbabilities(session.world().sheet, session.world().params, scratch);
            return scratch.probability;
        };
        // A step that broke and hinged nothing left the geometry the pass saw.
        auto creasesShowZero = [&] {
            const std::vector<float> shown = makeSnapshot(session.simulation()).breakProbability;
            const Springs& S = session.world().sheet.springs;
            for (Index k = 0; k < S.size(); ++k)
                if (S.kind[k] == SpringKind::Crease && shown[k] != 0.0f) return false;
            return true;
        };
        // A spring that broke in a step is a crease after it, and cannot break again.
        int toBreak = 0;
        while (session.simulation().lastBreaks() == 0 && toBreak < 2000) {
            session.advance(1);
            ++toBreak;
        }
        QVERIFY(session.simulation().lastBreaks() > 0);
        QVERIFY(creasesShowZero());
        int quiet = 0;
        while (quiet < 200) {
            session.advance(1);
            if (session.simulation().lastBreaks() == 0 && session.simulation().lastHinges() == 0)
                break;
            ++quiet;
        }
        QVERIFY(quiet < 200);
        const std::vector<float> drawn = makeSnapshot(session.simulation()).breakProbability;
        QCOMPARE(drawn, fresh());
        const auto compressed =
            std::count_if(drawn.begin(), drawn.end(), [](float p) { return p > 0.0f; });
        QVERIFY(compressed > 10); // the stroke left compressed edges to look at

        // The step's values are what the snapshot shows: change one and see it there.
        auto& cached = const_cast<std::vector<float>&>(session.simulation().breakProbabilities());
        cached[0] = 0.75f;
        QCOMPARE(makeSnapshot(session.simulation()).breakProbability[0], 0.75f);

        // φ weighs Eq. 10: a new φ while paused shows at once.
        SimParams p = session.world().params;
        p.phi = 0.9;
        session.setParams(p);
        const std::vector<float> afterPhi = makeSnapshot(session.simulation()).breakProbability;
        QCOMPARE(afterPhi, fresh());
        QVERIFY(afterPhi != drawn);

        // Undo changes the mesh: the overlay has one value per spring of the new one.
        session.undoStroke(0);
        const SheetSnapshot undone = makeSnapshot(session.simulation());
        QCOMPARE(undone.breakProbability.size(), undone.springEnds.size());
        QCOMPARE(undone.breakProbability, fresh());
    }

    // Settle: a crumpled, moving sheet steps on without damage until it rests (or 3 s
    // pass), then stands exactly still until the next edit; undo and redo like a stroke.
    void settleStopsDamageAndKeepsTheSheetAsItIs() {
        EditSession session(test::jacobiScene("press"));
        pushStroke(session, 0.0, 0.6);
        session.advance(6);
        const Index events = session.world().sheet.events.size();
        const std::vector<Vec3> chosenAt = session.world().sheet.verts.x;
        session.settle();
        QVERIFY(session.settling());
        std::optional<EditSession::StrokeEnd> settled;
        int steps = 0;
        for (; !settled && steps < 2000; ++steps) {
            QCOMPARE(session.advance(1), StepStatus::Ok);
            settled = session.takeFinished();
        }
        QVERIFY(settled);
        qInfo("settled after %d steps (%.2f s)", steps, steps * session.world().params.dt);
        QVERIFY(steps <= std::lround(EditSession::kSettleSeconds / session.world().params.dt));
        QVERIFY(session.frozen());
        QCOMPARE(session.world().sheet.events.size(), events); // no break, no hinge
        QVERIFY(!session.takeFinished());                      // reported once

        // Frozen: a minute of steps moves nothing; the clock runs.
        const std::vector<Vec3> kept = session.world().sheet.verts.x;
        const std::int64_t step = session.world().stepCount;
        session.advance(240 * 60);
        QCOMPARE(session.world().sheet.verts.x, kept);
        QCOMPARE(session.world().stepCount, step + 240 * 60);

        // Undo gives back the sheet as it was when Settle was chosen, moving again.
        QCOMPARE(session.undoStroke(settled->stroke), std::optional<int>(0));
        QVERIFY(!session.frozen());
        QCOMPARE(session.world().sheet.verts.x, chosenAt);
        session.advance(10);
        QVERIFY(session.world().sheet.verts.x != chosenAt);
        // Redo: the settled sheet, frozen again.
        QCOMPARE(session.redoStroke(settled->stroke), std::optional<int>(0));
        QVERIFY(session.frozen());
        QCOMPARE(session.world().sheet.verts.x, kept);
        session.advance(100);
        QCOMPARE(session.world().sheet.verts.x, kept);

        // The next edit ends the freeze: a press of the tool into the paper pushes again.
        // Its undo gives back the settled sheet, settled. (Along the press path again it
        // would touch no paper, the first stroke having ploughed it away, and leave the
        // sheet settled: aPushOnTheBareDeskLeavesASettledSheetSettled.)
        const auto pushed = pressInto(session, kept[kept.size() / 2]);
        QVERIFY(pushed);
        QVERIFY(!session.frozen());
        QVERIFY(session.world().sheet.verts.x != kept);
        session.undoStroke(pushed->stroke);
        QVERIFY(session.frozen());
        QCOMPARE(session.world().sheet.verts.x, kept);
        session.advance(100);
        QCOMPARE(session.world().sheet.verts.x, kept);

        // So does an undo of a Reset (a user's settled sheet came back moving, at 0.87x
        // real time), and its redo the fresh sheet, moving.
        const auto reset = session.reset(test::jacobiScene("press"));
        QVERIFY(reset);
        QVERIFY(!session.frozen());
        QCOMPARE(session.undoStroke(reset->stroke), std::optional<int>(0));
        QVERIFY(session.frozen());
        QCOMPARE(session.world().sheet.verts.x, kept);
        session.advance(100);
        QCOMPARE(session.world().sheet.verts.x, kept);
        QCOMPARE(session.redoStroke(reset->stroke), std::optional<int>(0));
        QVERIFY(!session.frozen());
        QCOMPARE(session.undoStroke(reset->stroke), std::optional<int>(0));
        QVERIFY(session.frozen());
    }

    // Under a held tool Settle does nothing: the push would go on through paper that
    // cannot break, and undo would mix the two.
    void settleIsRefusedWhileTheToolIsPressed() {
        EditSession session(test::machineryScene("press"));
        const double radius = session.world().sphere.radius;
        const Vec3 on = session.world().sheet.verts.x[0] + Vec3(0.0, radius * 0.5, 0.0);
        session.setTool(on, radius, true, true);
        session.settle();
        QVERIFY(!session.settling());
        session.advance(800);
        QVERIFY(!session.takeFinished());
    }

    // Settle is "keep it like this": a scene's motions wait while the sheet settles and
    // while it stands settled, and go on from where they stood at the next edit. (A
    // user's Settle of crumple-cycles mid-gather: its rim went on gathering and pulled
    // the sheet flat again while it settled.)
    void aSettleHoldsTheScenesMotionsStill() {
        World scene = test::machineryScene("crumple-cycles");
        const std::vector<Index> rim = scene.script.pins.front().vertices;
        const auto rimOf = [&](const EditSession& s) {
            std::vector<Vec3> at;
            for (Index i : rim) at.push_back(s.world().sheet.verts.x[i]);
            return at;
        };
        const int gather = static_cast<int>(std::lround(kCrumpleGather * 240));
        EditSession uninterrupted(scene);
        QCOMPARE(uninterrupted.advance(gather), StepStatus::Ok);
        EditSession session(std::move(scene));
        QCOMPARE(session.advance(gather / 2), StepStatus::Ok);
        const std::vector<Vec3> midGather = rimOf(session);
        QVERIFY(midGather != rimOf(uninterrupted)); // the rim was on its way
        session.settle();
        for (int k = 0; k < 2000 && session.settling(); ++k) {
            QCOMPARE(session.advance(1), StepStatus::Ok);
            QVERIFY(rimOf(session) == midGather);
        }
        QVERIFY(session.frozen());
        QCOMPARE(session.advance(240), StepStatus::Ok);
        QVERIFY(rimOf(session) == midGather);
        session.setParams(session.world().params); // an edit: the sheet moves on
        QVERIFY(!session.frozen());
        QCOMPARE(session.advance(gather - gather / 2), StepStatus::Ok);
        // The gather went on from where it stood, and ended where it ends.
        double off = 0.0;
        const std::vector<Vec3> gathered = rimOf(session), expected = rimOf(uninterrupted);
        for (std::size_t k = 0; k < rim.size(); ++k)
            off = std::max(off, (gathered[k] - expected[k]).norm());
        QVERIFY2(off < 1e-6, qPrintable(QString::number(off)));
    }

    // A push pressed on the bare desk beside a settled sheet moved nothing, yet ended the
    // freeze: the rim of crumple-cycles went on and pulled the sheet. It stays settled
    // until the tool comes near the paper, and thaws before the tool touches it.
    void aPushOnTheBareDeskLeavesASettledSheetSettled() {
        World scene = test::machineryScene("crumple-cycles");
        const std::vector<Index> rim = scene.script.pins.front().vertices;
        EditSession session(std::move(scene));
        const int halfGather = static_cast<int>(std::lround(kCrumpleGather * 120));
        QCOMPARE(session.advance(halfGather), StepStatus::Ok);
        session.settle();
        for (int k = 0; k < 2000 && session.settling(); ++k)
            QCOMPARE(session.advance(1), StepStatus::Ok);
        QVERIFY(session.frozen());
        const std::vector<Vec3> settled = session.world().sheet.verts.x;
        double farthest = 0.0; // from the origin, over the sheet
        for (const Vec3& x : settled) farthest = std::max(farthest, x.norm());
        const double radius = 0.03;
        const double onDesk = session.world().groundHeight + radius;

        // Pressed 10 cm beyond the sheet, it ploughs the desk for a second and lets go.
        const Vec3 beside(farthest + 0.1 + radius, onDesk, 0.0);
        session.setTool(beside, radius, true, false);
        QCOMPARE(session.advance(1), StepStatus::Ok);
        QVERIFY(!session.setTool(beside, radius, true, true));
        for (int k = 0; k < 240; ++k) {
            const double t = k / 240.0;
            session.setTool(beside + Vec3(0.05 * t, 0.0, 0.1 * std::sin(6.0 * t)), radius, true,
                            true);
            QCOMPARE(session.advance(1), StepStatus::Ok);
            QVERIFY(session.frozen());
        }
        QVERIFY(!session.setTool(beside, radius, true, false)); // no undo step: nothing moved
        QVERIFY(session.frozen());
        QVERIFY(session.world().sheet.verts.x == settled); // the rim too

        // Pressed and carried onto the sheet, it thaws the sheet before it reaches it.
        QVERIFY(!session.setTool(beside, radius, true, true));
        const Vec3 centre(0.0, onDesk, 0.0);
        bool thawed = false;
        for (int k = 0; k < 480 && !thawed; ++k) {
            session.setTool(centre, radius, true, true);
            const Vec3 at = session.world().sphere.center;
            double nearest = std::numeric_limits<double>::infinity();
            for (const Vec3& x : session.world().sheet.verts.x)
                nearest = std::min(nearest, (x - at).norm() - radius);
            QCOMPARE(session.advance(1), StepStatus::Ok);
            thawed = !session.frozen();
            if (!thawed) QVERIFY2(nearest > kToolReach, qPrintable(QString::number(nearest)));
        }
        QVERIFY(thawed);
        // Thawed, the scene goes on: the rim moves again.
        const Vec3 rimBefore = session.world().sheet.verts.x[rim.front()];
        QCOMPARE(session.advance(24), StepStatus::Ok);
        QVERIFY(session.world().sheet.verts.x[rim.front()] != rimBefore);
    }

    void aSessionWithASettleReplays() {
        EditSession session(test::machineryScene("press"));
        pushStroke(session, 0.0, 0.5);
        session.settle();
        session.advance(900);
        pushStroke(session, 0.5, 0.8);
        session.settle();
        session.advance(100);
        session.undoStroke(0);
        session.advance(30);
        checkReplays(session);
    }

    // Grab: the vertex follows the target at the tool's speed limit, the sheet hangs from
    // it, release lets it fall, and the grab is one undo step like a push.
    void aGrabCarriesTheVertexToTheTargetAndReleaseLetsItFall() {
        // Paper (xpbd): the jacobi default's sheet is rubber (issue 9), stretched by the
        // pull it springs up on release, 22 cm after 1.5 s, instead of falling.
        SceneOptions coarse; // a coarser sheet: xpbd's contacts are slow under sanitizers
        coarse.resolution = 9;
        World paper = test::machineryScene("press", coarse);
        paper.params.integrator = "xpbd";
        EditSession session(paper);
        const double dt = session.world().params.dt;
        const Vec3 corner = session.world().sheet.verts.x[0];
        const auto before = session.world().sheet.verts.x;
        const Vec3 picked = corner + Vec3(0.001, 0.0, 0.001);
        QVERIFY(!session.grab(picked, true, true));
        QCOMPARE(session.grabbedVertex(), Index(0));
        QVERIFY(session.world().sheet.verts.pinned[0]);
        // The hand moves the vertex as far as the cursor moves, from where it lay.
        const Vec3 target = corner + Vec3(0.02, 0.08, 0.0);
        session.grab(picked + (target - corner), true, false);
        session.advance(1);
        // The hand is drawn as a hand, not as a pin the user set (red crosses are pins).
        const SheetSnapshot held = makeSnapshot(session.simulation());
        QCOMPARE(held.held, std::vector<Index>{0});
        QVERIFY(held.pinned.empty());
        QVERIFY((session.world().sheet.verts.x[0] - corner).norm() <=
                EditSession::kMaxToolSpeed * dt * (1 + 1e-12));
        session.advance(119);
        const auto& V = session.world().sheet.verts;
        // Held by the hand's grip (kGripCompliance): the hanging paper's weight pulls it a
        // few hundredths of a millimetre below the hand.
        QVERIFY2((V.x[0] - target).norm() < 1e-4,
                 qPrintable(QString::number((V.x[0] - target).norm())));
        // The paper next to the corner hangs from it, above the desk.
        Index lifted = 0;
        for (Index i = 1; i < V.size(); ++i) lifted += V.x[i].y() > 0.02 ? 1 : 0;
        QVERIFY(lifted > 0);
        const auto ended = session.grab(picked + (target - corner), false, false);
        QVERIFY(ended);
        QCOMPARE(ended->kind, EditSession::StrokeKind::Grab);
        QVERIFY(!session.grabbing());
        QVERIFY(!session.world().sheet.verts.pinned[0]);
        session.advance(240);
        // It fell back onto the desk.
        QVERIFY(session.world().sheet.verts.x[0].y() < 0.005);
        const auto fallen = session.world().sheet.verts.x;
        QVERIFY(session.undoStroke(ended->stroke));
        QCOMPARE(session.world().sheet.verts.x, before);
        // Redo gives back the sheet as it lay when the user undid the grab.
        QVERIFY(session.redoStroke(ended->stroke));
        QCOMPARE(session.world().sheet.verts.x, fallen);
        QVERIFY(!session.world().sheet.verts.pinned[0]);
    }

    // The hand takes the paper where the cursor picks it: the nearest vertex keeps its
    // offset from the cursor. Drawn onto the cursor, a vertex picked a few millimetres
    // off was yanked across the desk in a step or two and the sheet broke at once (one
    // break from holding still, in three tries of three in the editor).
    void aGrabHoldsThePaperWhereItIsTaken() {
        SceneOptions options; // xpbd's sub-steps are slow under the sanitizers
        if (PAPERFOLD_TEST_SLOWDOWN > 1) options.resolution = 9;
        EditSession session(makeEditorScene("press", options, 0.03));
        QCOMPARE(session.advance(120), StepStatus::Ok); // lying still on the desk
        const auto& V = session.world().sheet.verts;
        Index corner = 0;
        for (Index i = 1; i < V.size(); ++i)
            if (V.x[i].x() + V.x[i].z() < V.x[corner].x() + V.x[corner].z()) corner = i;
        const Vec3 picked = V.x[corner] + Vec3(0.01, 0.0, 0.01); // a centimetre in
        QVERIFY(!session.grab(picked, true, true));
        const Index held = session.grabbedVertex();
        QVERIFY(held != kNone);
        const Vec3 start = V.x[held];
        const double off = (start - picked).norm();
        QVERIFY2(off > 0.002, qPrintable(QString::number(off))); // no vertex under the cursor
        const Index verticesBefore = V.size();
        for (int k = 0; k < 120; ++k) {
            session.grab(picked, true, false);
            QCOMPARE(session.advance(1), StepStatus::Ok);
        }
        const double drift = (V.x[held] - start).norm();
        qInfo("picked %.1f mm from its vertex: held still it moved %.3f mm, %d vertices added",
              off * 1e3, drift * 1e3, int(V.size() - verticesBefore));
        QVERIFY2(drift < 2e-4, qPrintable(QString::number(drift)));
        QCOMPARE(V.size(), verticesBefore); // nothing broke
        // Lifted five centimetres, the vertex rises five centimetres.
        const Vec3 lift(0.0, 0.05, 0.0);
        for (int k = 1; k <= 120; ++k) {
            session.grab(picked + lift * std::min(1.0, k / 60.0), true, false);
            QCOMPARE(session.advance(1), StepStatus::Ok);
        }
        const double miss = (V.x[held] - (start + lift)).norm();
        QVERIFY2(miss < 1e-3, qPrintable(QString::number(miss)));
        QCOMPARE(V.size(), verticesBefore);
    }

    // Three wheel notches while the hand holds a corner of the sheet lying on the desk:
    // each moves the hand's target a centimetre toward the eye (the editor's view, 35°
    // above the desk, beyond that corner). The hand follows at kMaxHandSpeed: at the
    // tool's 1.5 m/s the sheet was jerked, slid on past the hand and buckled against it
    // (a break and three hinges).
    void wheelNotchesLiftPaperWithoutBucklingIt() {
        SceneOptions options; // xpbd's sub-steps are slow under the sanitizers
        if (PAPERFOLD_TEST_SLOWDOWN > 1) options.resolution = 9;
        EditSession session(makeEditorScene("press", options, 0.03));
        QCOMPARE(session.advance(120), StepStatus::Ok);
        const auto& V = session.world().sheet.verts;
        Index corner = 0;
        for (Index i = 1; i < V.size(); ++i)
            if (V.x[i].x() + V.x[i].z() < V.x[corner].x() + V.x[corner].z()) corner = i;
        const Vec3 picked = V.x[corner] + Vec3(0.01, 0.0, 0.01);
        QVERIFY(!session.grab(picked, true, true));
        const Index held = session.grabbedVertex();
        const double elevation = 35.0 * std::numbers::pi / 180.0;
        const Vec3 towardTheEye = Vec3(-std::cos(elevation) / std::sqrt(2.0), std::sin(elevation),
                                       -std::cos(elevation) / std::sqrt(2.0));
        const double dt = session.world().params.dt;
        const SheetStats before = computeStats(session.world().sheet);
        Vec3 target = picked;
        double fastest = 0.0;
        for (int k = 0; k < 360; ++k) {
            if (k % 72 == 0 && k < 216) target += 0.01 * towardTheEye; // a notch
            session.grab(target, true, false);
            const Vec3 from = V.x[held];
            QCOMPARE(session.advance(1), StepStatus::Ok);
            fastest = std::max(fastest, (V.x[held] - from).norm() / dt);
        }
        const SheetStats after = computeStats(session.world().sheet);
        qInfo("the hand moved at most %.2f m/s; %d breaks, %d hinges", fastest,
              after.breaks - before.breaks, after.hinges - before.hinges);
        QVERIFY(fastest <= EditSession::kMaxHandSpeed * (1.0 + 1e-9));
        QCOMPARE(after.breaks, before.breaks);
        QCOMPARE(after.hinges, before.hinges);
        // It was lifted: three centimetres toward the eye, 1.7 cm up.
        QVERIFY2(V.x[held].y() > 0.015, qPrintable(QString::number(V.x[held].y())));
    }

    // The hand holds paper by a pinch (kHandForce), and the long-range tethers tie the
    // paper it lifts to the real pins, not to it: pinned flat at its four corners, the sheet
    // tents up a little in the middle and stops; pinned along one short edge, it swings
    // up about that edge, no higher than the paper between them reaches. (Held rigidly
    // and tethered, the hand tore the four-pinned sheet: 306 breaks and 454 % strain from
    // a 40 px drag upward in the editor, and the shredded sheet never came to rest.)
    void aGrabCannotTearPinnedPaper_data() {
        QTest::addColumn<int>("pins");
        QTest::newRow("four corners") << 4;
        QTest::newRow("one short edge") << 2;
    }
    void aGrabCannotTearPinnedPaper() {
        QFETCH(int, pins);
        SceneOptions coarse; // xpbd's sub-steps are slow under the sanitizers
        if (PAPERFOLD_TEST_SLOWDOWN > 1) coarse.resolution = 9;
        World paper = *makeScene("press", coarse);
        paper.script.sphereKeys.clear();
        paper.sphere.active = false;
        paper.params.integrator = "xpbd";
        EditSession session(paper);
        const auto& V = session.world().sheet.verts;
        const Index n = V.size();
        // The corners, farthest along ±x ± z; the sheet's long side is along z.
        std::vector<Index> corners;
        for (const Vec3& dir : {Vec3(1, 0, -1), Vec3(-1, 0, -1), Vec3(1, 0, 1), Vec3(-1, 0, 1)}) {
            Index best = 0;
            for (Index i = 1; i < n; ++i)
                if (V.x[i].dot(dir) > V.x[best].dot(dir)) best = i;
            corners.push_back(best);
        }
        corners.resize(static_cast<std::size_t>(pins));
        for (Index c : corners) QVERIFY(session.pin(V.x[c], 1e-4));
        Vec3 centre = Vec3::Zero();
        for (Index i = 0; i < n; ++i) centre += V.x[i] / double(n);
        QVERIFY(!session.grab(centre, true, true));
        const Index held = session.grabbedVertex();
        QVERIFY(held != kNone);
        const Vec3 start = V.x[held];
        session.grab(start + Vec3(0.0, 0.4, 0.0), true, false); // far beyond the paper
        const Index breaksBefore = computeStats(session.world().sheet).breaks;
        double worstStretch = 0.0;
        for (int k = 0; k < 360; ++k) {
            QCOMPARE(session.advance(1), StepStatus::Ok);
            worstStretch = std::max(worstStretch, computeStats(session.world().sheet).maxStretch);
        }
        const Sheet& sheet = session.world().sheet;
        const double rise = sheet.verts.x[held].y() - start.y();
        const SheetStats after = computeStats(sheet);
        qInfo("%d pins: rise %.1f mm, worst stretch %.2f %%, end stretch %.2f %%, %d breaks", pins,
              rise * 1e3, worstStretch * 100.0, after.maxStretch * 100.0,
              after.breaks - breaksBefore);
        if (pins == 4) {
            // It tents up about a centimetre, as the paper round it wrinkles, and stops.
            QVERIFY2(rise < 0.03, qPrintable(QString::number(rise)));
        } else {
            // About the pinned edge, at most as high as the paper between them is wide.
            const Vec2 a = sheet.verts.X[corners[0]], b = sheet.verts.X[corners[1]];
            const Vec2 p = sheet.verts.X[held], e = (b - a).normalized();
            const double across = ((p - a) - (p - a).dot(e) * e).norm();
            QVERIFY2(rise > 0.5 * across && rise <= across * 1.01,
                     qPrintable(QStringLiteral("rise %1 m, %2 m of paper to the pinned edge")
                                    .arg(rise)
                                    .arg(across)));
        }
        // Issue 9's bound, while the hand pulls against the pins: the projection iterates
        // until the stretch is down to 0.3 % where pins hold the paper (four iterations left
        // the four-pinned tent 4.7 % stretched; docs/material.md).
        QVERIFY2(worstStretch <= 0.01, qPrintable(QString::number(worstStretch)));
        QVERIFY(after.breaks <= breaksBefore + 10);
    }

    void aGrabNeverPullsThePaperBelowTheDesk() {
        EditSession session(test::machineryScene("press"));
        const Vec3 corner = session.world().sheet.verts.x[0];
        session.grab(corner, true, true);
        session.grab(corner - Vec3(0.0, 0.2, 0.0), true, false);
        session.advance(240);
        QVERIFY(session.world().sheet.verts.x[0].y() >= session.world().groundHeight);
    }

    void aGrabLeavesPinnedPaperAndThePushToolAlone() {
        EditSession session(test::machineryScene("press"));
        const Vec3 corner = session.world().sheet.verts.x[0];
        QVERIFY(session.pin(corner, 1e-4));
        session.grab(corner, true, true);
        QVERIFY(session.grabbing());
        QVERIFY(session.grabbedVertex() != 0); // the pin holds: its neighbour is taken
        session.grab(corner, false, false);
        const double radius = session.world().sphere.radius;
        session.setTool(corner + Vec3(0, radius, 0), radius, true, true);
        session.grab(corner, true, true);
        QVERIFY(!session.grabbing()); // one stroke at a time
    }

    // An undo lets a held grab go; moves of the hand that still holds nothing do not pick
    // up whatever is nearest, and the saved world has no pin where the hand held.
    void anUndoLetsAGrabGoAndOnlyABeginPicksUp() {
        EditSession session(test::machineryScene("press"));
        const Vec3 corner = session.world().sheet.verts.x[0];
        const auto pinned = session.pin(session.world().sheet.verts.x[5], 1e-4);
        QVERIFY(pinned);
        session.grab(corner, true, true);
        session.grab(corner + Vec3(0, 0.05, 0), true, false);
        session.advance(30);
        QVERIFY(session.grabbing());
        QVERIFY(!session.worldToSave().sheet.verts.pinned[0]);
        QVERIFY(session.worldToSave().sheet.verts.pinned[5]);
        QVERIFY(session.world().sheet.verts.pinned[0]);
        session.undoStroke(pinned->stroke);
        QVERIFY(!session.grabbing());
        QVERIFY(!session.world().sheet.verts.pinned[0]);
        session.grab(corner + Vec3(0, 0.06, 0), true, false);
        QVERIFY(!session.grabbing());
        QVERIFY(!session.grab(corner + Vec3(0, 0.06, 0), false, false));
    }

    // Unpinning wakes a sleeping sheet. (A hanging xpbd sheet swings for minutes with no
    // air to stop it, so the sleeping sheet here lies on the desk, pinned, and the desk
    // is then taken away under it without waking it: only the unpin can.)
    void unpinningWakesASleepingSheet() {
        SceneOptions coarse;
        coarse.resolution = 9;
        World w = test::machineryScene("press", coarse);
        w.params.integrator = "xpbd";
        EditSession session(w);
        const auto& V = session.world().sheet.verts;
        const Vec3 corner = V.x[0];
        QVERIFY(session.pin(corner, 0.02));
        for (int steps = 0; !session.simulation().asleep() && steps < 2400; steps += 10)
            session.advance(10);
        QVERIFY2(session.simulation().asleep(), "the sheet on the desk never came to rest");
        session.simulation().world().groundEnabled = false;
        const double before = V.x.back().y();
        session.advance(24);
        QCOMPARE(V.x.back().y(), before); // still asleep: nothing woke it
        const auto freed = session.pin(corner, 0.02);
        QVERIFY(freed);
        QCOMPARE(freed->kind, EditSession::StrokeKind::Unpin);
        session.advance(24);
        QVERIFY2(V.x.back().y() < before - 1e-3, "the unpinned sheet did not fall");
    }

    // A sheet at rest sleeps, and costs almost nothing (docs/speed.md); the tool wakes it
    // before it reaches the paper, and never passes into paper that sleeps. The desk is
    // taken away under the sleeping sheet (which does not wake it), so that nothing but
    // the paper can stop the tool pressed down through it.
    void theToolWakesASleepingSheetBeforeItTouches() {
        SceneOptions coarse;
        coarse.resolution = 9;
        const double radius = 0.03;
        World w = makeEditorScene("press", coarse, radius);
        w.params.integrator = "xpbd";
        EditSession session(w);
        const auto& V = session.world().sheet.verts;
        for (int steps = 0; !session.simulation().asleep() && steps < 2400; steps += 10)
            session.advance(10);
        QVERIFY2(session.simulation().asleep(), "the sheet on the desk never came to rest");
        session.simulation().world().groundEnabled = false;
        session.setTool(Vec3(0.0, 0.1, 0.0), radius, true, false);
        QCOMPARE(session.advance(24), StepStatus::Ok);
        QVERIFY(session.simulation().asleep()); // a hovering tool wakes nothing
        const double sheetAt = V.x[0].y();
        int woke = -1, reached = -1;
        double deepest = std::numeric_limits<double>::infinity();
        for (int step = 0; step < 60; ++step) {
            session.setTool(Vec3(0.0, -0.1, 0.0), radius, true, true);
            QCOMPARE(session.advance(1), StepStatus::Ok);
            // The tool meets the paper's triangles, mostly between vertices: each is
            // sampled on a grid of points about a millimetre apart.
            const SphereTool& sp = session.world().sphere;
            double nearest = std::numeric_limits<double>::infinity();
            constexpr int n = 24;
            for (const Triangle& t : session.world().sheet.tris)
                for (int i = 0; i <= n; ++i)
                    for (int j = 0; i + j <= n; ++j) {
                        const Vec3 p =
                            (i * V.x[t.v[0]] + j * V.x[t.v[1]] + (n - i - j) * V.x[t.v[2]]) /
                            double(n);
                        nearest = std::min(nearest, (p - sp.center).norm() - sp.radius);
                    }
            deepest = std::min(deepest, nearest);
            if (reached < 0 && nearest < kToolReach) reached = step;
            if (woke < 0 && !session.simulation().asleep()) woke = step;
        }
        const double toolAt = session.world().sphere.center.y();
        qInfo("woke at step %d, the tool reached the paper at step %d; the paper came %.3g mm "
              "from the tool's surface at the closest; the tool went %.1f cm below where the "
              "sheet slept",
              woke, reached, 1e3 * deepest, 1e2 * (sheetAt - toolAt));
        QVERIFY(toolAt < sheetAt - 0.05); // it went down through where the sheet was
        QVERIFY(reached >= 0);
        QVERIFY(woke >= 0 && woke < reached);
        QVERIFY(deepest > -1e-9); // and never had paper inside it
    }

    // A script that lets its pins go wakes a sleeping sheet, as the user's unpin does (the
    // Fold tool lets go this way: a sheet asleep under it stayed as the fold had left it).
    void aScriptLettingGoWakesASleepingSheet() {
        SceneOptions coarse;
        coarse.resolution = 9;
        World w = test::machineryScene("press", coarse);
        w.params.integrator = "xpbd";
        PinGroup hold;
        hold.vertices = {0};
        hold.release = 4.0;
        w.sheet.verts.pinned[0] = 1;
        w.script.pins.push_back(hold);
        EditSession session(w);
        const auto& V = session.world().sheet.verts;
        while (!session.simulation().asleep() && session.world().time < 3.5) session.advance(10);
        QVERIFY2(session.simulation().asleep(), "the sheet on the desk never came to rest");
        session.simulation().world().groundEnabled = false;
        const double before = V.x.back().y();
        session.advance(24);
        QCOMPARE(V.x.back().y(), before); // still asleep: nothing woke it
        while (session.world().time < hold.release) session.advance(1);
        QVERIFY(!V.pinned[0]);
        session.advance(24);
        QVERIFY2(V.x.back().y() < before - 1e-3, "the let-go sheet did not fall");
    }

    // A script's pinned vertex that the user freed and then grabs follows the hand, not
    // the script.
    void aGrabbedScriptVertexFollowsTheHand() {
        EditSession session(test::machineryScene("drape"));
        const auto& V = session.world().sheet.verts;
        Index scripted = kNone;
        for (Index i = 0; i < V.size() && scripted == kNone; ++i)
            if (V.pinned[i]) scripted = i;
        QVERIFY(scripted != kNone);
        const Vec3 at = V.x[scripted];
        QVERIFY(session.pin(at, 1e-5));
        QVERIFY(!V.pinned[scripted]);
        session.grab(at, true, true);
        QCOMPARE(session.grabbedVertex(), scripted);
        const Vec3 target = at + Vec3(0.03, 0.02, 0.01);
        session.grab(target, true, false);
        session.advance(120);
        // xpbd's hand holds it by a grip: the paper pulled taut between the hand and the
        // other pin draws it off by the grip's slack, at most its force × compliance.
        QVERIFY2((V.x[scripted] - target).norm() <= kHandForce * kGripCompliance,
                 qPrintable(QString::number((V.x[scripted] - target).norm())));
    }

    // Pin: the vertices around the click stand still while the rest falls; a second click
    // frees them; both are undo steps, and the pins are saved with the sheet.
    void aPinHoldsTogglesUndoesAndIsSaved() {
        EditSession session(test::machineryScene("drop"));
        const Vec3 at = session.world().sheet.verts.x[7];
        const double radius = 0.02;
        const auto pinned = session.pin(at, radius);
        QVERIFY(pinned);
        QCOMPARE(pinned->kind, EditSession::StrokeKind::Pin);
        QVERIFY(pinned->events >= 1);
        const auto& V = session.world().sheet.verts;
        std::vector<Index> held;
        for (Index i = 0; i < V.size(); ++i) {
            const bool near = (V.x[i] - at).norm() <= radius;
            QCOMPARE(bool(V.pinned[i]), near);
            if (near) held.push_back(i);
        }
        QCOMPARE(int(held.size()), pinned->events);
        const auto x0 = V.x;
        session.advance(240);
        double fell = 0.0;
        for (Index i = 0; i < Index(x0.size()); ++i) { // breaks may have added vertices
            if (V.pinned[i])
                QCOMPARE(V.x[i], x0[i]);
            else
                fell = std::max(fell, x0[i].y() - V.x[i].y());
        }
        QVERIFY2(fell > 0.05, qPrintable(QString::number(fell)));
        // Saved and loaded with the sheet.
        const auto decoded = decodeWorld(encodeWorld(session.world()));
        QVERIFY(decoded.world);
        QCOMPARE(decoded.world->sheet.verts.pinned, V.pinned);
        // A click on a pin frees the whole pin, even a little off where it was set (the
        // paper round a pin moves, so a second click never meets the first's point).
        const Vec3 off = at + Vec3(0.6 * radius, 0.0, 0.0);
        QVERIFY(std::any_of(V.x.begin(), V.x.end(), [&](const Vec3& x) {
            return (x - off).norm() > radius && (x - at).norm() <= radius;
        })); // some of the pin lies beyond the click's radius
        const auto freed = session.pin(off, radius);
        QVERIFY(freed);
        QCOMPARE(freed->kind, EditSession::StrokeKind::Unpin);
        QCOMPARE(freed->events, pinned->events);
        for (Index i = 0; i < V.size(); ++i) QVERIFY(!V.pinned[i]);
        QVERIFY(session.undoStroke(freed->stroke));
        for (Index i : held) QVERIFY(V.pinned[i]);
        QVERIFY(session.undoStroke(pinned->stroke));
        for (Index i = 0; i < V.size(); ++i) QVERIFY(!V.pinned[i]);
        QCOMPARE(V.x, x0);
        QVERIFY(session.redoStroke(pinned->stroke));
        for (Index i : held) QVERIFY(V.pinned[i]);
        QVERIFY(!session.pin(at + Vec3(0, 1, 0), radius)); // nothing that close: no step
    }

    // A click on free paper between two pins pins it, though both pins are within the
    // click's reach: a user pinning an edge in steps, who clicked the gap left between
    // two pins, saw a whole row of pins freed instead ("Unpin 12 vertices").
    void aClickBetweenTwoPinsPinsThePaperThere() {
        EditSession session(test::machineryScene("press"));
        const auto& V = session.world().sheet.verts;
        const auto nearestTo = [&](const Vec3& p) {
            Index best = 0;
            for (Index i = 1; i < V.size(); ++i)
                if ((V.x[i] - p).squaredNorm() < (V.x[best] - p).squaredNorm()) best = i;
            return best;
        };
        const Index middle = nearestTo(Vec3::Zero());
        // The next vertex along x on each side, one row spacing away.
        double spacing = std::numeric_limits<double>::infinity();
        for (Index i = 0; i < V.size(); ++i) {
            const Vec3 d = V.x[i] - V.x[middle];
            if (i != middle && std::abs(d.z()) < 1e-9) spacing = std::min(spacing, std::abs(d.x()));
        }
        QVERIFY(std::isfinite(spacing));
        const Index left = nearestTo(V.x[middle] - Vec3(spacing, 0, 0));
        const Index right = nearestTo(V.x[middle] + Vec3(spacing, 0, 0));
        QVERIFY(session.pin(V.x[left], 1e-4));
        QVERIFY(session.pin(V.x[right], 1e-4));
        QVERIFY(V.pinned[left] && V.pinned[right] && !V.pinned[middle]);

        const auto click = session.pin(V.x[middle] + Vec3(0.1 * spacing, 0, 0), 1.2 * spacing);
        QVERIFY(click);
        QCOMPARE(click->kind, EditSession::StrokeKind::Pin);
        QVERIFY(V.pinned[middle]);
        QVERIFY(V.pinned[left] && V.pinned[right]);
        // A click by a pin, with the free paper no nearer, frees it as before.
        const auto byPin = session.pin(V.x[left] - Vec3(0.2 * spacing, 0, 0), 1.2 * spacing);
        QVERIFY(byPin);
        QCOMPARE(byPin->kind, EditSession::StrokeKind::Unpin);
        QVERIFY(!V.pinned[left]);
        // That pin alone: the one the click between them set, and the right one, stay.
        QVERIFY(V.pinned[middle] && V.pinned[right]);
        const auto onMiddle = session.pin(V.x[middle], 1e-4);
        QVERIFY(onMiddle);
        QCOMPARE(onMiddle->kind, EditSession::StrokeKind::Unpin);
        QCOMPARE(onMiddle->events, click->events);
        QVERIFY(!V.pinned[middle] && V.pinned[right]);
        // Off the pin by more than a quarter of the radius, with free paper farther than
        // half as far again: still the pin's (paper round a pin it hangs from is steep).
        QVERIFY(session.pin(V.x[left], 1e-4));
        const Vec3 toMiddle = (V.x[middle] - V.x[left]).normalized();
        const auto nearPin = session.pin(V.x[left] + 0.42 * spacing * toMiddle, 1.2 * spacing);
        QVERIFY(nearPin);
        QCOMPARE(nearPin->kind, EditSession::StrokeKind::Unpin);
        QVERIFY(!V.pinned[left]);
        // And at 0.7 of the way, free paper less than half as far: pinned.
        QVERIFY(session.pin(V.x[left], 1e-4));
        const auto nearFree = session.pin(V.x[left] + 0.7 * spacing * toMiddle, 1.2 * spacing);
        QVERIFY(nearFree);
        QCOMPARE(nearFree->kind, EditSession::StrokeKind::Pin);
        QVERIFY(V.pinned[left] && V.pinned[middle]);
    }

    // A click on a pin frees that pin, as the click that set it pinned it: a helper
    // pinned three patches side by side, and one click on a pin freed all 14 vertices,
    // up to 37 mm away.
    void aClickOnAPinFreesThatPinOnly() {
        EditSession session(test::machineryScene("press"));
        const auto& V = session.world().sheet.verts;
        const double radius = 0.015;
        std::vector<std::vector<Index>> set;
        for (int k = -1; k <= 1; ++k) {
            const Vec3 at(0.025 * k, 0.0, 0.0);
            const auto click = session.pin(at, radius);
            QVERIFY(click);
            QCOMPARE(click->kind, EditSession::StrokeKind::Pin);
            set.emplace_back();
            for (Index i = 0; i < V.size(); ++i)
                if (V.pinned[i] && (V.x[i] - at).norm() <= radius &&
                    std::none_of(set.begin(), set.end() - 1, [&](const std::vector<Index>& p) {
                        return std::find(p.begin(), p.end(), i) != p.end();
                    }))
                    set.back().push_back(i);
            QCOMPARE(int(set.back().size()), click->events);
        }
        const auto pinnedCount = [&] { return std::count(V.pinned.begin(), V.pinned.end(), 1); };
        const auto all = pinnedCount();
        // The three are one patch of pinned paper joined by springs.
        QVERIFY(all > std::ptrdiff_t(set[1].size()) + 2);
        const auto freed = session.pin(V.x[set[1].front()], radius);
        QVERIFY(freed);
        QCOMPARE(freed->kind, EditSession::StrokeKind::Unpin);
        QCOMPARE(freed->events, int(set[1].size()));
        for (Index i : set[1]) QVERIFY(!V.pinned[i]);
        for (Index i : set[0]) QVERIFY(V.pinned[i]);
        for (Index i : set[2]) QVERIFY(V.pinned[i]);
        // Undone, the pin is back, and a click frees it again.
        QVERIFY(session.undoStroke(freed->stroke));
        QCOMPARE(pinnedCount(), all);
        const auto again = session.pin(V.x[set[1].back()], radius);
        QVERIFY(again);
        QCOMPARE(again->events, int(set[1].size()));
        // A sheet opened with pins on it has no clicks to go by: a click frees the patch
        // of pins round it, all three.
        QVERIFY(session.undoStroke(again->stroke));
        const auto opened = decodeWorld(encodeWorld(session.world()));
        QVERIFY(opened.world);
        EditSession reopened(*opened.world);
        const auto patch = reopened.pin(V.x[set[1].front()], radius);
        QVERIFY(patch);
        QCOMPARE(patch->events, int(all));
    }

    void aSessionWithGrabsAndPinsReplays() {
        EditSession session(test::machineryScene("press"));
        const Vec3 a = session.world().sheet.verts.x[0];
        const Vec3 b = session.world().sheet.verts.x[session.world().sheet.verts.size() - 1];
        session.pin(b, 0.02);
        session.advance(10);
        session.grab(a, true, true);
        for (int k = 0; k < 30; ++k) {
            session.grab(a + Vec3(0.003 * k, 0.004 * k, 0.0), true, false);
            session.advance(4);
        }
        const auto grabbed = session.grab(a + Vec3(0.09, 0.12, 0.0), false, false);
        QVERIFY(grabbed);
        session.advance(60);
        session.undoStroke(grabbed->stroke);
        session.advance(20);
        session.redoStroke(grabbed->stroke);
        session.advance(20);
        checkReplays(session);
    }

    // Reset is an undo step: the fresh sheet in place, the clock running on; strokes on
    // the fresh sheet undo as usual; undo of the Reset gives back the crumpled sheet bit
    // for bit, and then its own strokes undo again, while a stroke of the other sheet is
    // refused; redo resets again. The whole session replays, through the file too.
    // The clock runs on through a Reset, and the fresh sheet's scripted pins start their
    // motions then: crumple-cycles reset when its first gather ends gathers again from
    // the flat sheet and is back flat one cycle later (at the old times the pull came
    // first and drew the flat rim out to 1.7 times its size). Undone, the gathered sheet
    // goes on with its own cycle: held, pulled out flat.
    void aResetSceneStartsItsScriptWhenItIsReset() {
        World scene = test::machineryScene("crumple-cycles");
        scene.params.breaking = false;
        const World fresh = scene;
        const std::vector<Index> rim = fresh.script.pins.front().vertices;
        const auto rimIsBack = [&](const World& w) {
            for (Index i : rim)
                if ((w.sheet.verts.x[i] - fresh.sheet.verts.x[i]).norm() > 1e-9) return false;
            return true;
        };
        EditSession session(std::move(scene));
        const int gather = static_cast<int>(std::lround(kCrumpleGather * 240));
        const int cycle = static_cast<int>(std::lround(kCrumpleCycleSeconds * 240));
        QCOMPARE(session.advance(gather), StepStatus::Ok);
        const auto reset = session.reset(fresh);
        QVERIFY(reset.has_value());
        QCOMPARE(session.advance(gather), StepStatus::Ok);
        double widest = 0.0;
        for (Index i : rim)
            widest = std::max(widest, std::abs(session.world().sheet.verts.x[i].x()));
        QVERIFY2(widest < 0.5 * SceneOptions{}.width, qPrintable(QString::number(widest)));
        QCOMPARE(session.advance(cycle - gather), StepStatus::Ok);
        QVERIFY(rimIsBack(session.world()));
        QVERIFY(session.undoStroke(reset->stroke).has_value());
        QVERIFY(!rimIsBack(session.world()));
        const int squeezeAndPull =
            static_cast<int>(std::lround((kCrumpleSqueeze + kCrumpleGather) * 240));
        QCOMPARE(session.advance(squeezeAndPull), StepStatus::Ok);
        QVERIFY(rimIsBack(session.world()));
    }

    void resetIsAnUndoStepThatGivesTheSheetBack() {
        EditSession session(test::jacobiScene("press"));
        const World fresh = session.world();
        const auto crumple = pushStroke(session, 0.0, 0.6);
        QVERIFY(crumple && crumple->events > 0);
        QCOMPARE(session.advance(30), StepStatus::Ok);
        const Topology crumpled = topology(session.world().sheet);
        const std::uint64_t crumpledHash = stateHash(session.world().sheet);
        const std::int64_t stepBefore = session.world().stepCount;

        const auto reset = session.reset(fresh);
        QVERIFY(reset.has_value());
        QCOMPARE(reset->kind, EditSession::StrokeKind::Reset);
        QVERIFY(session.world().sheet.verts.x == fresh.sheet.verts.x);
        QCOMPARE(topology(session.world().sheet), topology(fresh.sheet));
        QCOMPARE(session.world().stepCount, stepBefore); // the clock runs on
        // A stroke of the crumpled sheet means nothing on this one.
        QCOMPARE(session.undoStroke(crumple->stroke), std::optional<int>());
        QCOMPARE(topology(session.world().sheet), topology(fresh.sheet));

        const auto again = pushStroke(session, 0.0, 0.4);
        QVERIFY(again.has_value());
        QCOMPARE(session.advance(12), StepStatus::Ok);
        QVERIFY(session.undoStroke(again->stroke).has_value());
        // Undo of the reset: the crumpled sheet as it was when Reset was chosen.
        const std::int64_t stepNow = session.world().stepCount;
        QCOMPARE(session.undoStroke(reset->stroke), std::optional<int>(0));
        QCOMPARE(topology(session.world().sheet), crumpled);
        QCOMPARE(stateHash(session.world().sheet), crumpledHash);
        QCOMPARE(session.world().stepCount, stepNow);
        // Its own strokes undo again: the damage recovered, flat as before the push.
        // (and those the sheet made settling after it)
        const auto recovered = session.undoStroke(crumple->stroke);
        QVERIFY(recovered && *recovered >= crumple->events);
        QCOMPARE_SHEET(session.world().sheet, fresh.sheet);
        // Redo: the crumpled sheet as it was when Reset was chosen, settling and all.
        QCOMPARE(session.redoStroke(crumple->stroke), recovered);
        QCOMPARE(topology(session.world().sheet), crumpled);
        // Redo resets again; a reset is refused while the tool is pressed.
        QCOMPARE(session.redoStroke(reset->stroke), std::optional<int>(0));
        QCOMPARE(topology(session.world().sheet), topology(fresh.sheet));
        QCOMPARE(session.advance(10), StepStatus::Ok);
        session.setTool(session.world().sphere.center, session.world().sphere.radius, true, true);
        QVERIFY(!session.reset(fresh).has_value());
        session.setTool(session.world().sphere.center, session.world().sphere.radius, true, false);
        checkReplays(session);
    }

    void aNewSheetForgetsTheStrokesButKeepsTheTool() {
        EditSession session(test::machineryScene("press"));
        QVERIFY(pushStroke(session, 0.0, 0.5).has_value());
        const double radius = 0.031;
        session.setTool(session.world().sphere.center, radius, true, false);
        session.replaceWorld(test::machineryScene("drape"));
        QVERIFY(!session.undoStroke(0).has_value());
        QCOMPARE(session.world().sphere.radius, radius);
        // Shown where the cursor is, not pressed into the paper.
        QVERIFY(session.world().sphere.hovering);
        QVERIFY(!session.world().sphere.active);
        QVERIFY(session.world().script.sphereKeys.empty());
    }

    void aRecordedSessionReplaysBitForBit() {
        EditSession live(test::machineryScene("press"));
        scriptedSession(live);
        const EditLog log = live.log();
        QVERIFY(log.commands.size() > 20);
        QCOMPARE(log.endStep, live.world().stepCount);

        // Through the file format, as `paperfold replay` reads it.
        const RecordingLoad load = decodeRecording(encodeRecording(log));
        QVERIFY2(load.log.has_value(), qPrintable(load.error));
        QCOMPARE(load.log->commands.size(), log.commands.size());
        EditSession again(*load.log);
        QCOMPARE(QString::fromStdString(replay(*load.log, again)), QString());
        QCOMPARE(again.world().stepCount, live.world().stepCount);
        QCOMPARE(hex(stateHash(again.world().sheet)), hex(stateHash(live.world().sheet)));
        QCOMPARE(again.world().sphere.center, live.world().sphere.center);
        QCOMPARE(again.world().params.phi, 0.4);
        // Everything, not only positions: damage log, rest lengths, clock, generator, paper.
        QVERIFY(encodeWorld(again.world()) == encodeWorld(live.world()));
        // The replay records itself: recording it again gives the same file.
        QCOMPARE(encodeRecording(again.log()), encodeRecording(log));
    }

    void aRecordingThatBeginsMidStrokeReplays() {
        // New while the button is held: the recording starts with the stroke under way,
        // and its undo must replay the same.
        EditSession live(test::machineryScene("press"));
        const auto path = makeScene("press")->script.sphereKeys;
        const double radius = live.world().sphere.radius;
        live.setTool(spherePathAt(path, 0.0), radius, true, true);
        QCOMPARE(live.advance(8), StepStatus::Ok);
        live.replaceWorld(test::machineryScene("press"));
        for (double t = 0.0; t < 0.5; t += 1.0 / 60.0) {
            live.setTool(spherePathAt(path, t), radius, true, true);
            QCOMPARE(live.advance(4), StepStatus::Ok);
        }
        const auto end = live.setTool(spherePathAt(path, 0.5), radius, true, false);
        QVERIFY(end.has_value());
        QCOMPARE(live.advance(20), StepStatus::Ok);
        live.undoStroke(end->stroke);
        QCOMPARE(live.advance(10), StepStatus::Ok);

        const EditLog log = live.log();
        QVERIFY(log.pressed);
        EditSession again(log);
        QCOMPARE(QString::fromStdString(replay(log, again)), QString());
        QCOMPARE(hex(stateHash(again.world().sheet)), hex(stateHash(live.world().sheet)));
        QVERIFY(encodeWorld(again.world()) == encodeWorld(live.world()));
    }

    void aSessionThatDivergedReplays() {
        // The explicit integrator at the editor's frame step blows up; the editor pauses,
        // the user picks the paper's integrator and plays on. The failed attempt (the tool
        // moved, the integrator restarted) is part of the session.
        World w = test::machineryScene("press");
        w.params.integrator = "symplectic";
        w.params.dt = 1.0 / 60.0;
        w.sheet.verts.x[100].y() += 0.002; // a flat sheet at rest has nothing to amplify
        EditSession live(w);
        int k = 0;
        while (live.advance(1) == StepStatus::Ok && k < 600) ++k;
        QVERIFY2(k < 600, "symplectic Euler at h = 1/60 must diverge");
        SimParams p = live.world().params;
        p.integrator = "jacobi";
        p.dt = 1.0 / 240.0;
        live.setParams(p);
        QCOMPARE(live.advance(30), StepStatus::Ok);
        const EditLog log = live.log();
        QVERIFY(std::any_of(log.commands.begin(), log.commands.end(), [](const EditCommand& c) {
            return c.kind == EditCommand::Kind::Diverged;
        }));
        const RecordingLoad load = decodeRecording(encodeRecording(log));
        QVERIFY2(load.log.has_value(), qPrintable(load.error));
        EditSession again(*load.log);
        QCOMPARE(QString::fromStdString(replay(*load.log, again)), QString());
        QVERIFY(encodeWorld(again.world()) == encodeWorld(live.world()));
    }

    void theScriptedSessionReachesItsPinnedHash() {
        // As Box2D's test_determinism.c: a fixed scene and command script must reach this
        // hash. A deliberate change of the model or the editing layer updates it in the
        // same commit; anything else that changes it is a bug.
        EditSession session(test::machineryScene("press"));
        scriptedSession(session);
        QCOMPARE(hex(stateHash(session.world().sheet)), QStringLiteral("45dc0cf57d798445"));
    }

    void aNewSheetStartsANewRecording() {
        EditSession session(test::machineryScene("press"));
        scriptedSession(session);
        session.replaceWorld(test::machineryScene("drape"));
        const EditLog log = session.log();
        QVERIFY(log.commands.empty());
        QCOMPARE(log.start.scene, std::string("drape"));
    }

    void badRecordingsAreRefusedWithOneLine_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("error");
        EditSession session(test::machineryScene("press"));
        scriptedSession(session);
        const EditLog log = session.log();
        const QByteArray good = encodeRecording(log);
        QTest::newRow("empty") << QByteArray() << "";
        QTest::newRow("a sheet, not a recording")
            << encodeWorld(log.start) << "a PaperFold sheet, not a recording";
        QTest::newRow("truncated") << good.left(good.size() / 2) << "";
        QTest::newRow("unknown command") << withCommandByte(log, 8, 12) << "unknown command";
        QTest::newRow("a fold without its line") << withCommandByte(log, 8, 11) << "no such fold";
        QTest::newRow("a reset without its sheet")
            << withCommandByte(log, 8, 10) << "no such sheet to reset to";
        QTest::newRow("unknown flags") << withCommandByte(log, 9, 4) << "unknown flags";
        QTest::newRow("a step from the future") << withCommandByte(log, 6, 1) << "out of order";
        QByteArray nan(8, '\0');
        qToLittleEndian(std::numeric_limits<double>::quiet_NaN(), nan.data());
        QTest::newRow("a NaN target") << withCommandBytes(log, 16, nan) << "outside the scene";
        QTest::newRow("a target 10^300 m away")
            << withCommandByte(log, 16 + 7, char(0x7e)) << "outside the scene";
        EditLog backwards = log;
        std::swap(backwards.commands.front().step, backwards.commands.back().step);
        QTest::newRow("steps going back") << encodeRecording(backwards) << "out of order";
        EditLog early = log;
        early.endStep = log.start.stepCount - 1;
        QTest::newRow("ends before it starts") << encodeRecording(early) << "endStep";
        EditLog badParams = log;
        for (EditCommand& c : badParams.commands)
            if (c.params) {
                SimParams p = *c.params;
                p.phi = 7.0;
                c.params = std::make_shared<const SimParams>(p);
            }
        QTest::newRow("φ out of range") << encodeRecording(badParams) << "params";
        const auto withEndState = [&](const QCborValue& state) {
            QCborMap root = QCborValue::fromCbor(good).toMap();
            root[QLatin1String("endState")] = state;
            return root.toCborValue().toCbor();
        };
        QTest::newRow("an end state of 15 digits")
            << withEndState(QStringLiteral("0123456789abcde")) << "endState";
        QTest::newRow("an end state that is no number")
            << withEndState(QStringLiteral("0123456789abcdeg")) << "endState";
        QTest::newRow("an end state as an integer") << withEndState(QCborValue(42)) << "endState";
    }

    // The state the session ended in goes with it, and comes back as written.
    void aRecordingKeepsTheStateItEndedIn() {
        EditSession session(test::machineryScene("press"));
        scriptedSession(session);
        const EditLog log = session.log();
        QCOMPARE(log.endState, std::optional(stateHash(session.world().sheet)));
        const RecordingLoad load = decodeRecording(encodeRecording(log));
        QVERIFY2(load.log, qPrintable(load.error));
        QCOMPARE(load.log->endState, log.endState);
        EditLog older = log;
        older.endState.reset();
        const RecordingLoad olderLoad = decodeRecording(encodeRecording(older));
        QVERIFY2(olderLoad.log, qPrintable(olderLoad.error));
        QVERIFY(!olderLoad.log->endState);
    }

    void badRecordingsAreRefusedWithOneLine() {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, error);
        const RecordingLoad load = decodeRecording(bytes);
        QVERIFY(!load.log.has_value());
        QVERIFY(!load.error.isEmpty());
        QVERIFY2(!load.error.contains(QLatin1Char('\n')), qPrintable(load.error));
        QVERIFY2(load.error.contains(error), qPrintable(load.error));
    }
};

QTEST_GUILESS_MAIN(TestEditSession)
#include "test_edit_session.moc"
