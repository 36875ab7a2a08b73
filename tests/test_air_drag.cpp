// The air resists a sheet's turning (sim/AirDrag.h) and nothing else: a plate turning
// broadside slows as quadratic drag says, a tumbling sheet still falls at exactly g with
// its momentum kept, and the swing of a sheet hanging from two corners dies down within
// seconds (it swung for more than a minute without air; a swing of a few millimetres
// still lingers, docs/material.md).
#include "AirDrag.h"
#include "Material.h"
#include "Scenes.h"
#include "SheetBuilder.h"
#include "Simulation.h"

#include <QTest>
#include <cmath>

using namespace pf;

namespace {

struct Motion {
    Vec3 centre = Vec3::Zero();
    Vec3 momentum = Vec3::Zero();
    double mass = 0.0;
    double kinetic = 0.0;
};

Motion motionOf(const Vertices& V) {
    Motion m;
    for (Index i = 0; i < V.size(); ++i) {
        m.mass += V.m[i];
        m.centre += V.m[i] * V.x[i];
        m.momentum += V.m[i] * V.v[i];
        m.kinetic += 0.5 * V.m[i] * V.v[i].squaredNorm();
    }
    m.centre /= m.mass;
    return m;
}

// The sheet's angular velocity about the x axis through its centre of mass, fitted to
// its velocities as a rigid rotation about that axis.
double spinAboutX(const Vertices& V) {
    const Vec3 c = motionOf(V).centre;
    double l = 0.0, inertia = 0.0;
    for (Index i = 0; i < V.size(); ++i) {
        const Vec3 r = V.x[i] - c;
        l += V.m[i] * r.cross(V.v[i]).x();
        inertia += V.m[i] * (r.y() * r.y() + r.z() * r.z());
    }
    return l / inertia;
}

} // namespace

class TestAirDrag : public QObject {
    Q_OBJECT

  private slots:
    // A rigid square plate of side H turning at ω about an axis in its plane: each strip
    // at distance y from the axis meets the air broadside at ω y, so the torque is
    // ∫ ½ ρ C_d (ω y)² |y| dA = ρ C_d ω² W H⁴ / 64 against I = ρ_A W H³ / 12, and
    // dω/dt = −(3 H / 8) k ω² with k = ρ C_d / (2 ρ_A): ω(t) = ω0 / (1 + (3 H / 8) k ω0 t).
    void aPlateTurningBroadsideSlowsAsQuadraticDragSays() {
        Material office;
        SheetSpec spec;
        spec.width = spec.length = 0.2;
        spec.columns = spec.rows = 61;
        spec.density = office.arealDensity;
        Sheet sheet = buildRectangleSheet(spec);
        const std::vector<Vec3> flat = sheet.verts.x;
        std::vector<Vec3> normals;
        const double dt = 1.0 / 240.0, omega0 = 10.0, seconds = 1.0;
        double angle = 0.0, omega = omega0;
        for (int step = 0; step < static_cast<int>(seconds / dt); ++step) {
            // The plate stays rigid: only its rotation is carried from step to step.
            const Eigen::AngleAxisd turn(angle, Vec3::UnitX());
            for (Index i = 0; i < sheet.verts.size(); ++i) {
                sheet.verts.x[i] = turn * flat[i];
                sheet.verts.v[i] = omega * Vec3::UnitX().cross(sheet.verts.x[i]);
            }
            dragTurningThroughAir(sheet, office.arealDensity, dt, normals);
            omega = spinAboutX(sheet.verts);
            angle += omega * dt;
        }
        const double k = kAirDensity * kPlateDragCoefficient / (2.0 * office.arealDensity);
        const double expected = omega0 / (1.0 + 3.0 * spec.length / 8.0 * k * omega0 * seconds);
        qInfo("spin after %.1f s: %.4f rad/s, quadratic drag on a square plate %.4f (from %.1f)",
              seconds, omega, expected, omega0);
        QVERIFY2(std::abs(omega / expected - 1.0) < 0.02, qPrintable(QString::number(omega)));
    }

    // Turning drag must not slow the fall: a sheet thrown tumbling end over end, with no
    // desk, keeps the momentum it was thrown with plus what gravity adds (its centre of
    // mass accelerates at exactly g), while its tumbling slows.
    void aTumblingSheetFallsAtGAndStopsTumbling() {
        World w = *makeScene("drop");
        w.params.integrator = "xpbd";
        w.params.breaking = false;
        w.groundEnabled = false;
        w.sphere.active = false;
        const Vec3 thrown(0.3, 0.5, -0.2);
        const double omega0 = 12.0; // rad/s, end over end about x
        const Vec3 c0 = motionOf(w.sheet.verts).centre;
        for (Index i = 0; i < w.sheet.verts.size(); ++i)
            w.sheet.verts.v[i] = thrown + omega0 * Vec3::UnitX().cross(w.sheet.verts.x[i] - c0);
        Simulation sim(std::move(w));
        sim.setThreads(1);
        const double dt = sim.world().params.dt, g = sim.world().params.gravity;
        const Motion start = motionOf(sim.world().sheet.verts);
        const int steps = 240;
        for (int s = 0; s < steps; ++s) QCOMPARE(sim.step(), StepStatus::Ok);
        const Motion end = motionOf(sim.world().sheet.verts);
        const double t = steps * dt;
        // Momentum as thrown, less what gravity took: m (v0 + g t).
        const Vec3 expected = start.momentum + start.mass * Vec3(0.0, -g * t, 0.0);
        const double drift = (end.momentum - expected).norm() / start.momentum.norm();
        const double spin = spinAboutX(sim.world().sheet.verts);
        qInfo("after %.1f s: momentum off by %.2e of the thrown, spin %.2f rad/s (from %.1f)", t,
              drift, spin, omega0);
        QVERIFY2(drift < 1e-9, qPrintable(QString::number(drift)));
        QVERIFY2(std::abs(spin) < 0.5 * omega0, qPrintable(QString::number(spin)));
        QVERIFY(spin > 0.0);
    }

    // The `drape` sheet as the editor starts it: hung from the two corners of a short
    // edge, it falls and swings about them. Falling from where it starts to where it
    // hangs releases m g Δh ≈ 7 mJ; without air it kept swinging with up to 2.5 mJ for
    // more than a minute (2.6 mJ of 5.5 mJ from 6 to 10 s). Real paper stops within a few
    // swings.
    void aHangingSheetsSwingDiesDownWithinSeconds() {
        World w = makeEditorScene("drape", {}, 0.02);
        Simulation sim(std::move(w));
        sim.setThreads(1);
        const double dt = sim.world().params.dt;
        const double top = motionOf(sim.world().sheet.verts).centre.y();
        double late = 0.0;
        for (int s = 0; s < static_cast<int>(10.0 / dt); ++s) {
            QCOMPARE(sim.step(), StepStatus::Ok);
            if (s * dt >= 6.0) late = std::max(late, motionOf(sim.world().sheet.verts).kinetic);
        }
        const Motion end = motionOf(sim.world().sheet.verts);
        const double released = end.mass * sim.world().params.gravity * (top - end.centre.y());
        qInfo("released by the fall %.2e J, largest kinetic energy from 6 to 10 s %.2e J", released,
              late);
        QVERIFY2(late < 0.01 * released, qPrintable(QString::number(late)));
    }
};

QTEST_APPLESS_MAIN(TestAirDrag)
#include "test_air_drag.moc"
