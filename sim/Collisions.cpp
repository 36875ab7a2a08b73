#include "Collisions.h"

namespace pf {

void collideSphere(Sheet& sheet, const SphereTool& sphere, double keepTangential,
                   WorkerPool& pool) {
    if (!sphere.active) return;
    auto& V = sheet.verts;
    const double r2 = sphere.radius * sphere.radius;
    pool.forRanges(V.size(), [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i) {
            if (V.pinned[i]) continue;
            const Vec3 d = V.x[i] - sphere.center;
            const double dist2 = d.squaredNorm();
            if (!(dist2 < r2)) continue;
            const double dist = std::sqrt(dist2);
            const Vec3 n = dist > 1e-12 ? Vec3(d / dist) : Vec3::UnitY();
            V.x[i] = sphere.center + sphere.radius * n;
            Vec3 rel = V.v[i] - sphere.velocity;
            const double vn = rel.dot(n);
            const Vec3 normalPart = std::max(vn, 0.0) * n;
            rel = normalPart + keepTangential * (rel - vn * n);
            V.v[i] = sphere.velocity + rel;
        }
    });
}

void collideGround(Sheet& sheet, double height, double keepTangential, WorkerPool& pool) {
    auto& V = sheet.verts;
    pool.forRanges(V.size(), [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i) {
            if (V.pinned[i] || !(V.x[i].y() < height)) continue;
            V.x[i].y() = height;
            Vec3& v = V.v[i];
            v.y() = std::max(v.y(), 0.0);
            v.x() *= keepTangential;
            v.z() *= keepTangential;
        }
    });
}

} // namespace pf
