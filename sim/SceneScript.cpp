#include "SceneScript.h"

#include <algorithm>
#include <cmath>

namespace pf {

Vec3 spherePathAt(const std::vector<SphereKey>& keys, double t) {
    if (t <= keys.front().time) return keys.front().center;
    for (std::size_t k = 1; k < keys.size(); ++k) {
        if (t <= keys[k].time) {
            const double span = keys[k].time - keys[k - 1].time;
            const double u = span > 0.0 ? (t - keys[k - 1].time) / span : 1.0;
            return (1.0 - u) * keys[k - 1].center + u * keys[k].center;
        }
    }
    return keys.back().center;
}

void applyScript(const SceneScript& script, double t, double h, Sheet& sheet, SphereTool& sphere,
                 Index held) {
    if (!script.sphereKeys.empty()) {
        const Vec3 next = spherePathAt(script.sphereKeys, t + h);
        sphere.velocity = (next - sphere.center) / h;
        sphere.center = next;
        sphere.active = true;
    }
    auto& V = sheet.verts;
    for (const PinGroup& g : script.pins) {
        if (t < g.release && t + h >= g.release) {
            for (Index i : g.vertices) V.pinned[i] = 0;
            sheet.paper.wake(); // what held it is gone
            continue;
        }
        if (t < g.start) {
            // A draw that begins inside this step moves for the part of the step after its
            // start, so that it scales by exactly e^(rate (until - start)) whatever the
            // step; drawing in and letting out again then brings the vertices back where
            // they were (two draws of the same vertices must not share a step).
            if (g.scaleRate == 0.0 || t + h <= g.start) continue;
        }
        const bool moving = t < g.until;
        // The exact chord of the turn over the step, so that positions stay on their
        // circles (integrated as x += h v) instead of spiralling outward.
        const Eigen::AngleAxisd turn(g.turnRate * h, g.axis);
        // A vertex the user has unpinned is the forces' again.
        for (Index i : g.vertices) {
            if (!V.pinned[i] || i == held) continue;
            if (!moving) {
                V.v[i].setZero();
                continue;
            }
            V.v[i] = g.velocity;
            const Vec3 arm = V.x[i] - g.pivot;
            if (g.turnRate != 0.0) V.v[i] += (turn * arm - arm) / h;
            if (g.scaleRate != 0.0) {
                const double span = std::min(t + h, g.until) - std::max(t, g.start);
                V.v[i] += std::expm1(g.scaleRate * span) / h * arm;
            }
        }
    }
}

void holdScriptStill(const SceneScript& script, Sheet& sheet, SphereTool& sphere, Index held) {
    if (!script.sphereKeys.empty()) sphere.velocity.setZero();
    auto& V = sheet.verts;
    for (const PinGroup& g : script.pins)
        for (Index i : g.vertices)
            if (V.pinned[i] && i != held) V.v[i].setZero();
}

} // namespace pf
