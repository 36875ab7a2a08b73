#include "Normals.h"

namespace pf {

void computeVertexNormals(const Sheet& sheet, std::vector<Vec3>& normals) {
    computeVertexNormals(sheet.verts.x, sheet.tris, normals);
}

namespace {

Vec3 faceNormal(const std::vector<Vec3>& x, const Triangle& t) {
    return (x[t.v[1]] - x[t.v[0]]).cross(x[t.v[2]] - x[t.v[0]]);
}

Vec3 unitOrUp(const Vec3& n) {
    const double len = n.norm();
    return len > 0.0 ? Vec3(n / len) : Vec3::UnitY();
}

} // namespace

void computeVertexNormals(const std::vector<Vec3>& x, const std::vector<Triangle>& tris,
                          std::vector<Vec3>& normals) {
    normals.assign(x.size(), Vec3::Zero());
    for (const Triangle& t : tris) {
        const Vec3 n = faceNormal(x, t);
        for (Index w : t.v) normals[w] += n;
    }
    for (Vec3& n : normals) n = unitOrUp(n);
}

void computeVertexNormals(const Sheet& sheet, std::vector<Vec3>& normals, WorkerPool& pool,
                          const VertexStars& stars, std::vector<Vec3>& triangleNormals) {
    const auto& x = sheet.verts.x;
    triangleNormals.resize(sheet.tris.size());
    pool.forRanges(sheet.triangleCount(), [&](Index begin, Index end) {
        for (Index t = begin; t < end; ++t) triangleNormals[t] = faceNormal(x, sheet.tris[t]);
    });
    normals.resize(x.size());
    pool.forRanges(sheet.verts.size(), [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i) {
            Vec3 sum = Vec3::Zero();
            for (const Index* t = stars.trianglesBegin(i); t != stars.trianglesEnd(i); ++t)
                sum += triangleNormals[*t];
            normals[i] = unitOrUp(sum);
        }
    });
}

} // namespace pf
