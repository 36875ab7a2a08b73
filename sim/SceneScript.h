#pragma once

#include "Collisions.h"
#include "Sheet.h"

#include <vector>

namespace pf {

// Scripted motion of a scene, as plain data so that it can be saved with the sheet.
struct SphereKey {
    double time = 0.0;
    Vec3 center = Vec3::Zero();
};

// Pinned vertices that move at a constant velocity until a time, then stand still.
struct PinGroup {
    std::vector<Index> vertices;
    Vec3 velocity = Vec3::Zero();
    double until = 0.0;
};

struct SceneScript {
    std::vector<SphereKey> sphereKeys; // piecewise-linear path; empty: the sphere is free
    std::vector<PinGroup> pins;
};

// Sets the sphere and the pinned vertices for the step from t to t + h: the sphere
// moves to its scripted position at t + h with the matching velocity; a group's vertices
// that are still pinned, but for `held` (one the user holds), get its velocity
// (positions then advance with the integrator).
void applyScript(const SceneScript& script, double t, double h, Sheet& sheet, SphereTool& sphere,
                 Index held = kNone);

// Position on the sphere path at time t (held constant outside the keys).
Vec3 spherePathAt(const std::vector<SphereKey>& keys, double t);

} // namespace pf
