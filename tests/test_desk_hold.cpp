// Coulomb's law for the sheet as a whole on the desk (sim/DeskHold): the rigid creep
// across the desk that friction would have stopped within the step is undone, a slide
// faster than that or down a desk steeper than friction holds goes on, and the shape of
// the sheet is never touched. The bounds are worked out here from μ, g and dt.
#include "DeskHold.h"
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"

#include <QTest>
#include <cmath>

using namespace pf;

namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 240.0;
constexpr double kKinetic = 0.35;

// A 5 × 5 grid of 1 cm cells lying on the desk (y = 0), its centre at (0.3, 0, -0.2).
Vertices grid() {
    Vertices V;
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c) {
            V.x.push_back(Vec3(0.3 + 0.01 * (c - 2), 0.0, -0.2 + 0.01 * (r - 2)));
            V.v.push_back(Vec3::Zero());
            V.m.push_back(8e-6);
            V.X.push_back(Vec2(0.01 * c, 0.01 * r));
            V.pinned.push_back(0);
        }
    return V;
}

DeskHoldScene flatDesk() {
    return {Vec3(0.0, -kG, 0.0), kDt, kKinetic};
}

// A desk tilted about z so that gravity pulls along x with tan α.
DeskHoldScene tiltedDesk(double tanAlpha) {
    const double alpha = std::atan(tanAlpha);
    return {kG * Vec3(std::sin(alpha), -std::cos(alpha), 0.0), kDt, kKinetic};
}

// Moves every vertex by shift and turns it by theta about the vertical through the
// grid's centre, as the fit reads a turn (θ ŷ × r), and gives it the matching velocity.
void moveRigidly(Vertices& V, const Vec3& shift, double theta) {
    const Vec3 centre(0.3, 0.0, -0.2);
    for (Index i = 0; i < V.size(); ++i) {
        const Vec3 r = V.x[i] - centre;
        const Vec3 d = shift + theta * Vec3(r.z(), 0.0, -r.x());
        V.x[i] += d;
        V.v[i] = d / kDt;
    }
}

double farthest(const Vertices& V, const std::vector<Vec3>& from) {
    double d = 0.0;
    for (Index i = 0; i < V.size(); ++i) d = std::max(d, (V.x[i] - from[i]).norm());
    return d;
}

// How much a slide across the flat desk must slow at least in one step (m/s): what
// kinetic friction takes out of it, the sheet's whole weight pressing it on the desk.
constexpr double kLeastSlowing = kKinetic * kG * kDt;

const std::vector<std::uint8_t> kAll(25, 1);

// The editor's sheet lying flat on the desk, without breaks or hinges.
World flatSheetOnTheDesk() {
    World w = makeEditorScene("press", SceneOptions{}, 0.03);
    w.params.integrator = "xpbd";
    w.params.breaking = w.params.hinges = false;
    return w;
}

} // namespace

class TestDeskHold : public QObject {
    Q_OBJECT

  private slots:
    void aSheetAtRestStaysAtRest() {
        // A folded sheet crept 1-1.3 mm/s, as a rigid body, with nothing pushing it.
        Vertices V = grid();
        const std::vector<Vec3> start = V.x;
        moveRigidly(V, Vec3(1.2e-3 * kDt, 0.0, -0.4e-3 * kDt), 0.02 * kDt);
        QVERIFY(farthest(V, start) > 4e-6);
        double slide = 0.0;
        QVERIFY(holdOnDesk(V, start, kAll, flatDesk(), slide));
        QVERIFY2(farthest(V, start) < 1e-12, qPrintable(QString::number(farthest(V, start))));
        for (const Vec3& v : V.v) QVERIFY(v.norm() < 1e-9); // its rigid velocity goes too
        QCOMPARE(slide, 0.0);
    }

    void aSlideSlowsAtLeastAsFrictionSlowsIt() {
        const double before = 0.034; // m/s, as fast as one folded card walked
        for (const double now :
             {before, before - 0.9 * kLeastSlowing, before - 1.1 * kLeastSlowing}) {
            Vertices V = grid();
            const std::vector<Vec3> start = V.x;
            moveRigidly(V, Vec3(0.6, 0.0, 0.8) * (now * kDt), 0.0);
            const std::vector<Vec3> moved = V.x;
            double slide = before;
            const bool cut = holdOnDesk(V, start, kAll, flatDesk(), slide);
            const double allowed = before - kLeastSlowing;
            QCOMPARE(cut, now > allowed);
            QVERIFY(std::abs(slide - std::min(now, allowed)) < 1e-12);
            // The step's move, cut to the allowed speed, or left as it was.
            QVERIFY(std::abs(farthest(V, start) - std::min(now, allowed) * kDt) < 1e-15);
            if (!cut) QCOMPARE(V.x, moved);
        }
    }

    void aSlideThatWasNotMeasuredGoesOn() {
        Vertices V = grid();
        const std::vector<Vec3> start = V.x;
        moveRigidly(V, Vec3(0.5 * kDt, 0.0, 0.0), 0.0);
        const std::vector<Vec3> moved = V.x;
        double slide = kSlideUnknown;
        QVERIFY(!holdOnDesk(V, start, kAll, flatDesk(), slide));
        QCOMPARE(V.x, moved);
        QVERIFY(std::abs(slide - 0.5) < 1e-12);
    }

    void aDrivenSlideStopsAndStaysStopped() {
        // Something drives the sheet at 34 mm/s every step, as the sub-steps' swing did a
        // folded card: it stops within the steps friction needs, and stays.
        double slide = kSlideUnknown;
        const int needed = static_cast<int>(std::ceil(0.034 / kLeastSlowing));
        Vertices V = grid();
        for (int step = 0; step < needed + 10; ++step) {
            const std::vector<Vec3> start = V.x;
            moveRigidly(V, Vec3(0.034 * kDt, 0.0, 0.0), 0.0);
            holdOnDesk(V, start, kAll, flatDesk(), slide);
            if (step >= needed)
                QCOMPARE(farthest(V, start), 0.0);
            else
                QVERIFY(farthest(V, start) > 0.0);
        }
        QCOMPARE(slide, 0.0);
    }

    void aTurnCountsWhereTheContactsAre() {
        // The turn's speed is taken at the contacts' root mean square distance from
        // their centre.
        Vertices V = grid();
        double inertia = 0.0;
        for (const Vec3& x : V.x) inertia += (x - Vec3(0.3, 0.0, -0.2)).squaredNorm();
        const double radius = std::sqrt(inertia / 25.0);
        for (const double share : {0.98, 1.02}) {
            Vertices W = grid();
            const std::vector<Vec3> start = W.x;
            const double before = 0.05;
            moveRigidly(W, Vec3::Zero(), share * (before - kLeastSlowing) * kDt / radius);
            double slide = before;
            QCOMPARE(holdOnDesk(W, start, kAll, flatDesk(), slide), share > 1.0);
        }
    }

    void aSteepDeskLetsTheSheetSlide() {
        // Below atan μk the pull down the slope takes its part of friction's slowing.
        const double gentle = 0.2;
        const double pull = kG * std::sin(std::atan(gentle));
        const double pressing = kG * std::cos(std::atan(gentle));
        const double least = (kKinetic * pressing - pull) * kDt;
        for (const double share : {0.98, 1.02}) {
            Vertices V = grid();
            const std::vector<Vec3> start = V.x;
            moveRigidly(V, Vec3((0.01 - share * least) * kDt, 0.0, 0.0), 0.0);
            double slide = 0.01;
            QCOMPARE(holdOnDesk(V, start, kAll, tiltedDesk(gentle), slide), share < 1.0);
        }
        // Beyond atan μk a sliding sheet speeds up: the sub-steps' own friction decides.
        Vertices V = grid();
        const std::vector<Vec3> start = V.x;
        moveRigidly(V, Vec3(1e-6, 0.0, 0.0), 0.0);
        double slide = 0.0;
        QVERIFY(!holdOnDesk(V, start, kAll, tiltedDesk(kKinetic + 0.02), slide));
        QCOMPARE(slide, kSlideUnknown);
    }

    void theShapeIsNeverTouched() {
        // The fit takes only the vertices on the desk; what the rest of the sheet does
        // relative to them (a flap lifting, an edge drawn in) stays.
        Vertices V = grid();
        const std::vector<Vec3> start = V.x;
        std::vector<std::uint8_t> contact = kAll;
        for (Index i = 20; i < 25; ++i) contact[i] = 0; // the last row is lifted off
        for (Index i = 20; i < 25; ++i) V.x[i] += Vec3(0.0, 1e-5, -2e-5);
        const std::vector<Vec3> shaped = V.x;
        moveRigidly(V, Vec3(3e-6, 0.0, 1e-6), 0.0);
        double slide = 0.0;
        QVERIFY(holdOnDesk(V, start, contact, flatDesk(), slide));
        for (Index i = 0; i < V.size(); ++i) QVERIFY((V.x[i] - shaped[i]).norm() < 1e-12);
    }

    void aSheetThatLandsOrTopplesIsNotMeasured() {
        // Its lifted part may push the part on the desk: while the sheet as a whole
        // falls faster than μk·g·dt, the sub-steps' friction alone decides.
        Vertices V = grid();
        const std::vector<Vec3> start = V.x;
        for (Index i = 0; i < 5; ++i) V.x[i].y() += 0.02; // the first row still above
        std::vector<std::uint8_t> contact = kAll;
        for (Index i = 0; i < 5; ++i) contact[i] = 0;
        for (Index i = 0; i < 5; ++i) V.x[i].y() -= 0.02 + 1.1 * 5.0 * kKinetic * kG * kDt * kDt;
        moveRigidly(V, Vec3(1e-6, 0.0, 0.0), 0.0);
        const std::vector<Vec3> moved = V.x;
        double slide = 0.0;
        QVERIFY(!holdOnDesk(V, start, contact, flatDesk(), slide));
        QCOMPARE(slide, kSlideUnknown);
        QCOMPARE(V.x, moved);
    }

    void aThrownSheetSlidesAsFarAsCoulombSays() {
        // The rule must not cut a real slide short: a flat sheet thrown across the desk
        // at u stops after u² / (2 μk g) under the sub-steps' friction, and the rule binds
        // only on a slide that slows less.
        World w = flatSheetOnTheDesk();
        const double u = 0.3; // m/s
        for (Vec3& v : w.sheet.verts.v) v = Vec3(u, 0.0, 0.0);
        const double mu = w.params.material.groundKineticFriction;
        const double g = w.params.gravity;
        Simulation sim(std::move(w));
        const Vec3 from = centreOfMass(sim.world().sheet);
        bool measured = false;
        for (int k = 0; k < 240 && !sim.asleep(); ++k) {
            QCOMPARE(sim.step(), StepStatus::Ok);
            measured = measured || sim.world().sheet.paper.deskSlide > 0.01;
        }
        QVERIFY(sim.asleep());
        QVERIFY(measured); // the rule watched the slide
        const double slid = (centreOfMass(sim.world().sheet) - from).x();
        const double coulomb = u * u / (2.0 * mu * g);
        qInfo("slid %.2f mm; u^2 / (2 mu_k g) = %.2f mm", 1e3 * slid, 1e3 * coulomb);
        QVERIFY(std::abs(slid / coulomb - 1.0) < 0.05);
    }

    void aTurnCreepingAboutItsPinIsStopped() {
        // Hanging from one still pin with a corner on the desk, office paper turned about
        // the vertical through the pin for good (0.12-0.14 rad/s). A turn that grows from
        // one step to the next is cut back to what friction leaves of the one before, as
        // a rigid turn about the pin: no length changes and the pin stays.
        Vertices V = grid();
        V.pinned[0] = 1;
        const Vec3 pin = V.x[0];
        const std::vector<Vec3> start = V.x;
        const double theta = 0.1 * kDt; // 0.1 rad/s
        for (Index i = 1; i < V.size(); ++i) {
            const Vec3 r = V.x[i] - pin;
            const Vec3 d(r.x() * std::cos(theta) + r.z() * std::sin(theta) - r.x(), 0.0,
                         r.z() * std::cos(theta) - r.x() * std::sin(theta) - r.z());
            V.x[i] += d;
            V.v[i] = d / kDt;
        }
        // The desk pushes each vertex up by its weight over the step; the pin's grid
        // turns under μk g Σ m r / Σ m r², about 9 rad/s² for a 4 cm grid.
        std::vector<double> pushed(25, 0.0), lengths;
        double moment = 0.0, inertia = 0.0;
        for (Index i = 1; i < V.size(); ++i) {
            pushed[i] = V.m[i] * kG * kDt;
            const double r = (start[i] - pin).norm();
            moment += V.m[i] * r;
            inertia += V.m[i] * r * r;
        }
        for (Index i = 1; i < V.size(); ++i) lengths.push_back((V.x[i] - V.x[i - 1]).norm());
        const double slowing = kKinetic * kG * moment / inertia;
        double rate = 0.05; // rad/s at the step before, slower than now
        QVERIFY(holdTurnOnDesk(V, pin, start, pushed, flatDesk(), rate));
        QCOMPARE(rate, std::max(0.0, 0.05 - slowing * kDt));
        QCOMPARE(V.x[0], pin);
        double turned = 0.0, weight = 0.0;
        for (Index i = 1; i < V.size(); ++i) {
            const Vec3 r = start[i] - pin, d = V.x[i] - start[i];
            turned += V.m[i] * (r.z() * d.x() - r.x() * d.z());
            weight += V.m[i] * r.squaredNorm();
            QVERIFY(std::abs(d.y()) < 1e-15);
            QVERIFY(std::abs((V.x[i] - V.x[i - 1]).norm() - lengths[i - 1]) < 1e-12);
            QVERIFY((V.v[i] - d / kDt).norm() < 1e-12);
        }
        // (The fit of a turn by φ reads sin φ: the same to 1e-11 of a radian here.)
        QVERIFY(std::abs(turned / weight / kDt - rate) < 1e-8);
        // Slowing by that much or more, it is left alone.
        const std::vector<Vec3> kept = V.x;
        double before = rate + slowing * kDt + 1e-6;
        QVERIFY(!holdTurnOnDesk(V, pin, start, pushed, flatDesk(), before));
        QCOMPARE(V.x, kept);
        // Off the desk (nothing pushed up), or on a tilted one, it is not measured.
        double unknown = 0.2;
        QVERIFY(!holdTurnOnDesk(V, pin, start, std::vector<double>(25, 0.0), flatDesk(), unknown));
        QCOMPARE(unknown, kSlideUnknown);
        unknown = 0.2;
        QVERIFY(!holdTurnOnDesk(V, pin, start, pushed, tiltedDesk(0.1), unknown));
        QCOMPARE(unknown, kSlideUnknown);
        QCOMPARE(V.x, kept);
    }

    void aSheetTurnedAboutItsPinTurnsAsFarAsCoulombSays() {
        // The rule must not cut a real turn short: a flat sheet pinned at a corner and
        // set turning about the vertical through the pin at ω stops after ω² / (2 α),
        // α = μk g Σ m r / Σ m r², under the sub-steps' friction.
        World w = flatSheetOnTheDesk();
        auto& V = w.sheet.verts;
        V.pinned[0] = 1;
        const Vec3 pin = V.x[0];
        double moment = 0.0, inertia = 0.0, reach = 0.0;
        for (Index i = 1; i < V.size(); ++i) {
            const Vec3 r = V.x[i] - pin;
            moment += V.m[i] * r.norm();
            inertia += V.m[i] * r.squaredNorm();
            reach = std::max(reach, r.norm());
        }
        const double omega = 0.3 / reach; // the far corner at 0.3 m/s
        for (Index i = 1; i < V.size(); ++i) {
            const Vec3 r = V.x[i] - pin;
            V.v[i] = omega * Vec3(r.z(), 0.0, -r.x());
        }
        const double mu = w.params.material.groundKineticFriction;
        const double alpha = mu * w.params.gravity * moment / inertia;
        Simulation sim(std::move(w));
        const Vec3 far = sim.world().sheet.verts.x.back() - pin;
        bool measured = false;
        for (int k = 0; k < 240 && !sim.asleep(); ++k) {
            QCOMPARE(sim.step(), StepStatus::Ok);
            measured = measured || sim.world().sheet.paper.deskSlide > 0.01;
        }
        QVERIFY(sim.asleep());
        QVERIFY(measured); // the rule watched the turn
        const Vec3 now = sim.world().sheet.verts.x.back() - pin;
        const double turned = std::atan2(far.z() * now.x() - far.x() * now.z(),
                                         far.x() * now.x() + far.z() * now.z());
        const double coulomb = omega * omega / (2.0 * alpha);
        qInfo("turned %.4f rad; omega^2 / (2 alpha) = %.4f rad", turned, coulomb);
        QVERIFY(std::abs(turned / coulomb - 1.0) < 0.05);
    }

    void nothingButTheDeskMustActOnTheSheet() {
        // Two pins hold the sheet: the step measures no slide, and no turn.
        World w = makeEditorScene("press", SceneOptions{}, 0.03);
        w.params.integrator = "xpbd";
        w.sheet.verts.pinned[0] = 1;
        w.sheet.verts.pinned[1] = 1;
        for (Vec3& v : w.sheet.verts.v) v = Vec3(0.05, 0.0, 0.0);
        w.sheet.verts.v[0] = w.sheet.verts.v[1] = Vec3::Zero();
        Simulation sim(std::move(w));
        for (int k = 0; k < 10; ++k) {
            QCOMPARE(sim.step(), StepStatus::Ok);
            QCOMPARE(sim.world().sheet.paper.deskSlide, kSlideUnknown);
        }
    }

    void nothingOnTheDeskIsNotHeld() {
        Vertices V = grid();
        const std::vector<Vec3> start = V.x;
        moveRigidly(V, Vec3(1e-6, 0.0, 0.0), 0.0);
        const std::vector<Vec3> moved = V.x;
        double slide = 0.0;
        QVERIFY(!holdOnDesk(V, start, std::vector<std::uint8_t>(25, 0), flatDesk(), slide));
        QCOMPARE(V.x, moved);
        QCOMPARE(slide, kSlideUnknown);
    }
};

QTEST_APPLESS_MAIN(TestDeskHold)
#include "test_desk_hold.moc"
