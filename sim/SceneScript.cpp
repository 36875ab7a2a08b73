#include "SceneScript.h"

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
    for (const PinGroup& g : script.pins) {
        const Vec3 v = t < g.until ? g.velocity : Vec3::Zero();
        // A vertex the user has unpinned is the forces' again.
        for (Index i : g.vertices)
            if (sheet.verts.pinned[i] && i != held) sheet.verts.v[i] = v;
    }
}

} // namespace pf
