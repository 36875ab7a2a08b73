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

// The least-squares rigid motion across the desk of the vertices in contact, from
// where each was (from) to where it is (to): a shift and a small turn.
template <typename From, typename To>
RigidMotion fitRigidMotion(const Vertices& V, const std::vector<std::uint8_t>& contact, From from,
                           To to) {
    RigidMotion r;
    double mass = 0.0;
    for (Index i = 0; i < V.size(); ++i) {
        if (!contact[i]) continue;
        mass += V.m[i];
        r.centre += V.m[i] * from(i);
        r.shift += V.m[i] * (to(i) - from(i));
    }
    r.centre /= mass;
    r.centre.y() = 0.0;
    r.shift /= mass;
    r.shift.y() = 0.0;
    double torque = 0.0, inertia = 0.0;
    for (Index i = 0; i < V.size(); ++i) {
        if (!contact[i]) continue;
        Vec3 arm = from(i) - r.centre;
        arm.y() = 0.0;
        const Vec3 d = to(i) - from(i) - r.shift;
        torque += V.m[i] * (arm.z() * d.x() - arm.x() * d.z());
        inertia += V.m[i] * arm.squaredNorm();
    }
    r.theta = inertia > 0.0 ? torque / inertia : 0.0;
    r.radius = std::sqrt(inertia / mass);
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
    const RigidMotion moved = fitRigidMotion(
        V, contact, [&](Index i) { return stepStart[i]; }, [&](Index i) { return V.x[i]; });
    const double speed =
        std::max(moved.shift.norm(), std::abs(moved.theta) * moved.radius) / scene.dt;
    const double allowed =
        slide < 0.0 ? speed : std::max(0.0, slide - kFrictionShare * slowing * scene.dt);
    if (speed <= allowed) {
        slide = speed;
        return false;
    }
    // What the slide gained beyond friction's bound is undone, in position and in
    // velocity alike (the position-based step's velocity is its move over dt).
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

} // namespace pf
