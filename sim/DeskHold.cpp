#include "DeskHold.h"

#include <algorithm>
#include <cmath>

namespace pf {

namespace {

// The turn about the desk's normal (y) that moves a point at r by θ·ŷ×r.
Vec3 turn(double theta, const Vec3& r) {
    return Vec3(theta * r.z(), 0.0, -theta * r.x());
}

struct RigidMotion {
    Vec3 centre = Vec3::Zero(); // mass centre of the vertices on the desk, across it
    Vec3 shift = Vec3::Zero();  // across the desk (y = 0)
    double theta = 0.0;         // turn about the desk's normal through centre
    double radius = 0.0;        // root mean square distance from centre
};

// The least-squares rigid motion across the desk of the vertices in contact, from where
// each was (from) to where it is (to): a shift and a small turn.
RigidMotion fitRigidMotion(const std::vector<double>& mass,
                           const std::vector<std::uint8_t>& contact, const std::vector<Vec3>& from,
                           const std::vector<Vec3>& to) {
    RigidMotion r;
    double total = 0.0;
    for (std::size_t i = 0; i < from.size(); ++i) {
        if (!contact[i]) continue;
        total += mass[i];
        r.centre += mass[i] * from[i];
        r.shift += mass[i] * (to[i] - from[i]);
    }
    if (!(total > 0.0)) return {};
    r.centre /= total;
    r.centre.y() = 0.0;
    r.shift /= total;
    r.shift.y() = 0.0;
    double turning = 0.0, inertia = 0.0; // Σ m (r × d)·ŷ and Σ m |r|², r across the desk
    for (std::size_t i = 0; i < from.size(); ++i) {
        if (!contact[i]) continue;
        Vec3 arm = from[i] - r.centre;
        arm.y() = 0.0;
        const Vec3 d = to[i] - from[i] - r.shift;
        turning += mass[i] * (arm.z() * d.x() - arm.x() * d.z());
        inertia += mass[i] * arm.squaredNorm();
    }
    r.theta = inertia > 0.0 ? turning / inertia : 0.0;
    r.radius = std::sqrt(inertia / total);
    return r;
}

} // namespace

bool holdOnDesk(Vertices& V, const std::vector<Vec3>& stepStart,
                const std::vector<std::uint8_t>& contact, const DeskHoldScene& scene,
                double& slide) {
    const double pressing = -scene.gravity.y();
    const double pulling = Vec3(scene.gravity.x(), 0.0, scene.gravity.z()).norm();
    const double slowing = scene.kineticFriction * pressing - pulling; // m/s²
    const bool touching =
        std::any_of(contact.begin(), contact.end(), [](std::uint8_t c) { return c != 0; });
    if (!(slowing > 0.0) || !(scene.dt > 0.0) || !touching) {
        slide = kSlideUnknown;
        return false;
    }
    // While the sheet as a whole rises or falls faster than that (it lands, topples, or
    // a flap falls onto the rest), its lifted part pushes the part on the desk, and
    // the sub-steps' own friction decides: the slide is not measured.
    double mass = 0.0, rise = 0.0;
    for (Index i = 0; i < V.size(); ++i) {
        mass += V.m[i];
        rise += V.m[i] * (V.x[i].y() - stepStart[i].y());
    }
    if (!(std::abs(rise / mass) <= scene.kineticFriction * pressing * scene.dt * scene.dt)) {
        slide = kSlideUnknown;
        return false;
    }
    const RigidMotion moved = fitRigidMotion(V.m, contact, stepStart, V.x);
    const double speed =
        std::max(moved.shift.norm(), std::abs(moved.theta) * moved.radius) / scene.dt;
    const double allowed = slide < 0.0 ? speed : std::max(0.0, slide - slowing * scene.dt);
    if (speed <= allowed) {
        slide = speed;
        return false;
    }
    // What the slide gained beyond friction's bound is undone, and the velocities lose
    // the same motion over the step. Not the rigid part of the velocities themselves:
    // they are the last sub-step's, and carry the sub-steps' cycle; taking that out
    // instead (tried, with an earlier form of this rule) set two folded cards walking
    // at 11 and 82 mm/s.
    const double undone = 1.0 - allowed / speed;
    for (Index i = 0; i < V.size(); ++i) {
        Vec3 arm = stepStart[i] - moved.centre;
        arm.y() = 0.0;
        const Vec3 undo = undone * (moved.shift + turn(moved.theta, arm));
        V.x[i] -= undo;
        V.v[i] -= undo / scene.dt;
    }
    slide = allowed;
    return true;
}

bool holdTurnOnDesk(Vertices& V, const Vec3& pin, const std::vector<Vec3>& stepStart,
                    const std::vector<double>& deskImpulse, const DeskHoldScene& scene,
                    double& turnRate) {
    // A tilted desk pulls the sheet around the pin; the rule is for a level one.
    const bool level = scene.gravity.x() == 0.0 && scene.gravity.z() == 0.0;
    double mass = 0.0, rise = 0.0, inertia = 0.0, turning = 0.0, holding = 0.0;
    for (Index i = 0; i < V.size(); ++i) {
        if (V.pinned[i]) continue;
        Vec3 arm = stepStart[i] - pin;
        arm.y() = 0.0;
        const Vec3 d = V.x[i] - stepStart[i];
        mass += V.m[i];
        rise += V.m[i] * d.y();
        inertia += V.m[i] * arm.squaredNorm();
        turning += V.m[i] * (arm.z() * d.x() - arm.x() * d.z());
        holding += deskImpulse[i] * arm.norm();
    }
    if (!level || !(scene.dt > 0.0) || !(holding > 0.0) || !(inertia > 0.0)) {
        turnRate = kSlideUnknown;
        return false;
    }
    // As for a sheet free on the desk: while it rises or falls as a whole, it is landing
    // or swinging, and the sub-steps' own friction decides.
    const double pressing = -scene.gravity.y();
    if (!(std::abs(rise / mass) <= scene.kineticFriction * pressing * scene.dt * scene.dt)) {
        turnRate = kSlideUnknown;
        return false;
    }
    const double theta = turning / inertia; // over the step
    const double rate = std::abs(theta) / scene.dt;
    const double slowing = scene.kineticFriction * holding / (inertia * scene.dt); // rad/s²
    const double allowed = turnRate < 0.0 ? rate : std::max(0.0, turnRate - slowing * scene.dt);
    if (rate <= allowed) {
        turnRate = rate;
        return false;
    }
    // Turned back exactly (not by the fit's small-angle move), so that no edge to the
    // pin stretches.
    const double back = -(1.0 - allowed / rate) * theta;
    const double c = std::cos(back), s = std::sin(back);
    for (Index i = 0; i < V.size(); ++i) {
        if (V.pinned[i]) continue;
        const Vec3 r = V.x[i] - pin;
        const Vec3 to = pin + Vec3(c * r.x() + s * r.z(), r.y(), c * r.z() - s * r.x());
        V.v[i] += (to - V.x[i]) / scene.dt;
        V.x[i] = to;
    }
    turnRate = allowed;
    return true;
}

} // namespace pf
