#include "Picking.h"

namespace pf {

std::optional<PickHit> pickSheet(const SheetSnapshot& snapshot, const OrbitCamera::Ray& ray) {
    std::optional<PickHit> best;
    const auto& x = snapshot.x;
    for (const Triangle& t : snapshot.tris) {
        // Möller–Trumbore.
        const Vec3 e1 = x[t.v[1]] - x[t.v[0]], e2 = x[t.v[2]] - x[t.v[0]];
        const Vec3 p = ray.direction.cross(e2);
        const double det = e1.dot(p);
        if (std::abs(det) < 1e-14) continue;
        const Vec3 s = ray.origin - x[t.v[0]];
        const double u = s.dot(p) / det;
        if (u < 0.0 || u > 1.0) continue;
        const Vec3 q = s.cross(e1);
        const double v = ray.direction.dot(q) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        const double d = e2.dot(q) / det;
        if (d <= 0.0 || (best && d >= best->distance)) continue;
        Vec3 n = e1.cross(e2).normalized();
        if (n.dot(ray.direction) > 0.0) n = -n;
        best = PickHit{ray.origin + d * ray.direction, n, d, true};
    }
    if (best || !snapshot.groundEnabled) return best;
    if (std::abs(ray.direction.y()) < 1e-12) return std::nullopt;
    const double d = (snapshot.groundHeight - ray.origin.y()) / ray.direction.y();
    if (d <= 0.0) return std::nullopt;
    return PickHit{ray.origin + d * ray.direction, Vec3::UnitY(), d, false};
}

Vec3 toolCenter(const PickHit& hit, double radius, double depth) {
    return hit.point + (radius - depth) * hit.normal;
}

} // namespace pf
