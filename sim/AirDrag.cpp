#include "AirDrag.h"

#include "Normals.h"
#include "PinPivot.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pf {

namespace {

// A sheet that turns about its pins as a pendulum swings to and fro through the same
// air: how far it swings (an angle, from hanging), about which axis, and how wide it
// is along that axis (the breadth the air flows around).
struct Swing {
    Vec3 axis = Vec3::Zero();
    double amplitude = 0.0; // rad; 0 when the sheet does not swing as a pendulum
    double breadth = 0.0;   // m
    double frequency = 0.0; // Ω, rad/s; 0 when the sheet does not swing as a pendulum
};

// A pendulum at angle θ from hanging turning at ω_a has the amplitude
// √(θ² + (ω_a / Ω)²), Ω² = m g⊥ d⊥ / I_a (exact for a small swing, and a measure of
// how far it goes for a large one). A free sheet, or one held at its centre of mass,
// or turning about the vertical, has no pull back to swing about.
template <class Turns>
Swing swingOf(const Vertices& V, const Turns& turns, const Pivot& pivot, const Vec3& omega,
              const Vec3& centre, double mass, const Eigen::Matrix3d& inertia,
              const Vec3& gravity) {
    Swing s;
    if (pivot.kind != Pivot::Kind::Point && pivot.kind != Pivot::Kind::Axis) return s;
    const Vec3 a = pivot.kind == Pivot::Kind::Axis ? pivot.axis : Vec3(omega.normalized());
    const Vec3 arm = centre - pivot.point;
    const Vec3 armAcross = arm - arm.dot(a) * a;
    const Vec3 pullAcross = gravity - gravity.dot(a) * a;
    const double aboutAxis = a.dot(inertia * a);
    const double pull = mass * pullAcross.norm() * armAcross.norm();
    if (!(pull > 0.0) || !(aboutAxis > 0.0)) return s;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (Index i = 0; i < V.size(); ++i) {
        if (!turns(i)) continue;
        const double along = (V.x[i] - pivot.point).dot(a);
        lo = std::min(lo, along);
        hi = std::max(hi, along);
    }
    const double angle = std::atan2(a.dot(armAcross.cross(pullAcross)), armAcross.dot(pullAcross));
    const double turning = omega.dot(a);
    s.axis = a;
    s.amplitude = std::sqrt(angle * angle + turning * turning * aboutAxis / pull);
    s.breadth = hi - lo;
    s.frequency = std::sqrt(pull / aboutAxis);
    return s;
}

// What is left of each vertex's velocity once the sheet's rigid motion (its drift and
// its turning ω about o) is taken out, the sheet flapping, fluttering or twisting
// between its pins, meets the air too, vertex by vertex along its normal, at the
// steady plate's drag `k` per unit of u². Only what is left: neighbours across a crease
// that move together move rigidly and are not pulled apart (the drag on whole
// velocities along each normal stretched crumpled tissue 10.5 %). What that drag would
// do to the rigid motion is taken back out of it: its net impulse on a free sheet
// (`freeMass` > 0), so the centre of mass moves as without air, and its turn
// (`rotationFor` of its angular impulse about o), which the drag on the rigid turn
// deals with. So it only slows what is left, and takes energy without ever adding
// any: the rigid motion and what is left are orthogonal in the kinetic energy, and the
// drag only shrinks what is left before what is rigid in its change is removed.
template <class Turns, class RotationFor>
void dragDeformingThroughAir(Vertices& V, const Turns& turns, const std::vector<Vec3>& normals,
                             const Vec3& o, const Vec3& drift, const Vec3& omega, double k,
                             double dt, double freeMass, const RotationFor& rotationFor) {
    Vec3 impulse = Vec3::Zero(), angularImpulse = Vec3::Zero();
    for (Index i = 0; i < V.size(); ++i) {
        if (!turns(i)) continue;
        const Vec3& n = normals[i];
        const Vec3 r = V.x[i] - o;
        const double u = (V.v[i] - drift - omega.cross(r)).dot(n);
        const Vec3 slowed = (u / (1.0 + dt * k * std::abs(u)) - u) * n;
        V.v[i] += slowed;
        impulse += V.m[i] * slowed;
        angularImpulse += V.m[i] * r.cross(slowed);
    }
    const Vec3 back = freeMass > 0.0 ? Vec3(impulse / freeMass) : Vec3::Zero();
    Vec3 turnBack = rotationFor(angularImpulse);
    if (!turnBack.allFinite()) turnBack = Vec3::Zero();
    for (Index i = 0; i < V.size(); ++i)
        if (turns(i)) V.v[i] -= back + turnBack.cross(V.x[i] - o);
}

} // namespace

double airSkinFriction(double swingFrequency, double arealDensity) {
    if (!(swingFrequency > 0.0) || !(arealDensity > 0.0)) return 0.0;
    return kAirDensity * std::sqrt(2.0 * kAirKinematicViscosity * swingFrequency) / arealDensity;
}

double oscillatingPlateDrag(double displacementAmplitude, double breadth) {
    if (!(displacementAmplitude > 0.0) || !(breadth > 0.0)) return kPlateDragCoefficient;
    const double kc = 2.0 * std::numbers::pi * displacementAmplitude / breadth;
    return std::max(kPlateDragCoefficient, 8.0 / std::cbrt(kc));
}

void dragThroughAir(Sheet& sheet, double arealDensity, const Vec3& gravity, double dt,
                    std::vector<Vec3>& normals, bool toolPressed) {
    auto& V = sheet.verts;
    const Index nv = V.size();
    if (!(arealDensity > 0.0) || !(dt > 0.0)) return;
    Pivot pivot = pivotOf(V);
    if (pivot.kind == Pivot::Kind::Held) return;
    const auto turns = [&](Index i) { return !V.pinned[i] && V.m[i] > 0.0; };
    double mass = 0.0;
    Vec3 centre = Vec3::Zero(), momentum = Vec3::Zero();
    for (Index i = 0; i < nv; ++i) {
        if (!turns(i)) continue;
        mass += V.m[i];
        centre += V.m[i] * V.x[i];
        momentum += V.m[i] * V.v[i];
    }
    if (!(mass > 0.0) || !momentum.allFinite()) return; // a blown-up step is not the air's
    const bool free = pivot.kind == Pivot::Kind::Free;
    // A free sheet turns about its centre of mass, which goes on as it was.
    const Vec3 drift = free ? Vec3(momentum / mass) : Vec3::Zero();
    if (free) pivot.point = centre / mass;
    const Vec3 o = pivot.point;
    // The rigid rotation that carries the sheet's angular momentum about the pivot:
    // ω = I⁻¹ L, about the axis only where pins in a row allow no other.
    Vec3 angular = Vec3::Zero();
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    for (Index i = 0; i < nv; ++i) {
        if (!turns(i)) continue;
        const Vec3 r = V.x[i] - o;
        angular += V.m[i] * r.cross(V.v[i] - drift);
        inertia += V.m[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    const Eigen::LDLT<Eigen::Matrix3d> solve(inertia);
    const auto rotationFor = [&](const Vec3& moment) -> Vec3 {
        if (pivot.kind == Pivot::Kind::Axis) {
            const Vec3& a = pivot.axis;
            const double about = a.dot(inertia * a);
            return about > 0.0 ? Vec3(moment.dot(a) / about * a) : Vec3::Zero();
        }
        // A sheet folded to a line has no inertia about it, and nothing to turn broadside.
        if (solve.info() != Eigen::Success ||
            !(solve.vectorD().minCoeff() > 1e-12 * inertia.trace()))
            return Vec3::Zero();
        return solve.solve(moment);
    };
    Vec3 omega = rotationFor(angular);
    if (!omega.allFinite()) omega = Vec3::Zero();
    if (toolPressed && omega.isZero(0.0)) return; // no flutter drag and no turn to slow
    computeVertexNormals(sheet, normals);
    const double perCoefficient = kAirDensity / (2.0 * arealDensity);
    if (!toolPressed)
        dragDeformingThroughAir(V, turns, normals, o, drift, omega,
                                perCoefficient * kPlateDragCoefficient, dt, free ? mass : 0.0,
                                rotationFor);
    if (omega.isZero(0.0)) return;

    // Each vertex's broadside speed in that rotation meets the drag of its own area of
    // paper; the torque of those drags slows the rotation as a whole. Taken as a rigid
    // change, it leaves the sheet's shape alone: applied vertex by vertex along the
    // normals of crumpled paper, it pulled neighbours apart (tissue's crumple-cycles
    // reached 10.5 % stretch). A sheet swinging from its pins meets the drag of a plate
    // in oscillating flow, each vertex at the width of its own swing, and its motion
    // along the paper meets the viscous drag of the air's Stokes layer.
    const Swing swing = swingOf(V, turns, pivot, omega, centre / mass, mass, inertia, gravity);
    const double skin = airSkinFriction(swing.frequency, arealDensity);
    Vec3 angularImpulse = Vec3::Zero();
    for (Index i = 0; i < nv; ++i) {
        if (!turns(i)) continue;
        const Vec3 r = V.x[i] - o;
        const Vec3& n = normals[i];
        const Vec3 u = omega.cross(r);
        const double un = u.dot(n);
        // (A sheet that does not swing has no amplitude and meets the steady drag.)
        const double reach = (r - r.dot(swing.axis) * swing.axis).norm();
        const double k =
            perCoefficient * oscillatingPlateDrag(swing.amplitude * reach, swing.breadth);
        angularImpulse += V.m[i] * (un / (1.0 + dt * k * std::abs(un)) - un) * r.cross(n);
        const Vec3 along = u - un * n;
        angularImpulse += V.m[i] * r.cross(along / (1.0 + dt * skin) - along);
    }
    const Vec3 slowing = rotationFor(angularImpulse);
    if (!slowing.allFinite()) return;
    for (Index i = 0; i < nv; ++i)
        if (turns(i)) V.v[i] += slowing.cross(V.x[i] - o);
}

} // namespace pf
