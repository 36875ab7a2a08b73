#pragma once

#include "Collisions.h"
#include "Sheet.h"

#include <limits>
#include <vector>

namespace pf {

// Scripted motion of a scene, as plain data so that it can be saved with the sheet.
struct SphereKey {
    double time = 0.0;
    Vec3 center = Vec3::Zero();
};

// Pinned vertices that move from a time until a time, then stand still: at a constant
// velocity, turning at a constant rate about an axis, drawn toward or away from a point,
// or any of these together; optionally let go at a time. Before its start a group leaves its
// vertices to whatever moves them (another group of the same vertices, say: one motion after
// another).
struct PinGroup {
    std::vector<Index> vertices;
    Vec3 velocity = Vec3::Zero();
    // Turning about the line through `pivot` along the unit vector `axis`, in rad/s
    // (right-handed); 0: no turning.
    Vec3 pivot = Vec3::Zero();
    Vec3 axis = Vec3::UnitX();
    double turnRate = 0.0;
    // Drawn toward `pivot` (negative) or away from it, as a hand gathers paper in: the
    // offset from the pivot scales by e^(scaleRate t), in 1/s; 0: no scaling.
    double scaleRate = 0.0;
    double start = -std::numeric_limits<double>::infinity();
    double until = 0.0;
    // The step that reaches this time unpins the group's vertices; infinity: never.
    double release = std::numeric_limits<double>::infinity();
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

// The script's motions stopped: its pinned vertices (but `held`) and its sphere keep
// still for the step.
void holdScriptStill(const SceneScript& script, Sheet& sheet, SphereTool& sphere,
                     Index held = kNone);

// Position on the sphere path at time t (held constant outside the keys).
Vec3 spherePathAt(const std::vector<SphereKey>& keys, double t);

} // namespace pf
