#include "Picking.h"

#include "TriangleGeometry.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace pf {

std::optional<Index> pinMarkOnRay(const SheetSnapshot& snapshot, const OrbitCamera::Ray& ray,
                                  double spread) {
    std::optional<Index> found;
    double nearest = std::numeric_limits<double>::infinity();
    for (Index i : snapshot.pinned) {
        if (i < 0 || static_cast<std::size_t>(i) >= snapshot.x.size()) continue;
        const Vec3 d = snapshot.x[static_cast<std::size_t>(i)] - ray.origin;
        const double along = d.dot(ray.direction);
        if (!(along > 0.0) || !(along < nearest)) continue;
        if ((d - along * ray.direction).norm() <= kPinMarkArm + spread * along) {
            nearest = along;
            found = i;
        }
    }
    return found;
}

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

Vec3 restingToolCenter(const SheetSnapshot& snapshot, const OrbitCamera::Ray& ray,
                       const PickHit& hit, double radius) {
    const Vec3 start = toolCenter(hit, radius, 0.0);
    const double maxLift = 3.0 * radius;
    // The triangles the sphere can meet on its way: within its radius of the path.
    const auto& x = snapshot.x;
    std::vector<const Triangle*> near;
    for (const Triangle& t : snapshot.tris) {
        const Vec3 middle = (x[t.v[0]] + x[t.v[1]] + x[t.v[2]]) / 3.0;
        double reach = 0.0;
        for (Index v : t.v) reach = std::max(reach, (x[v] - middle).norm());
        if ((middle - start).norm() < reach + radius + maxLift) near.push_back(&t);
    }
    const auto clearance = [&](const Vec3& p) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Triangle* t : near) {
            const Vec3& a = x[t->v[0]];
            const Vec3& b = x[t->v[1]];
            const Vec3& c = x[t->v[2]];
            const Vec3 w = closestPointBarycentric(a, b, c, p);
            nearest = std::min(nearest, (w[0] * a + w[1] * b + w[2] * c - p).norm());
        }
        return nearest;
    };
    // The distance to the paper grows at most as fast as the sphere moves, so each move
    // by what is missing never overshoots; it ends in a few moves (3-24 over the fold
    // scene's sheet).
    double lift = 0.0;
    for (int k = 0; k < 100; ++k) {
        const double missing = radius - clearance(start - lift * ray.direction);
        if (missing <= 1e-6 * radius) break;
        lift = std::min(maxLift, lift + missing + 1e-6 * radius);
        if (lift == maxLift) break;
    }
    return start - lift * ray.direction;
}

} // namespace pf
