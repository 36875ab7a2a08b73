#include "Subdivision.h"

#include "Normals.h"

#include <algorithm>
#include <utility>

namespace pf {

Vec3 hermiteMidpoint(const Vec3& xi, const Vec3& xj, const Vec3& ni, const Vec3& nj, double sigma) {
    const Vec3 v = sigma * (xj - xi);
    const Vec3 d0 = v - v.dot(ni) * ni;
    const Vec3 d1 = v - v.dot(nj) * nj;
    return 0.5 * (xi + xj) + 0.125 * (d0 - d1);
}

Vec3 midpointNormal(const Vec3& ni, const Vec3& nj) {
    const Vec3 s = ni + nj;
    const double len = s.norm();
    // Opposite normals (a fully folded edge) have no mean; keep the first.
    return len > 1e-12 ? Vec3(s / len) : ni;
}

SurfaceMesh subdivideSheet(const Sheet& sheet, double sigma, int levels) {
    return subdivide(sheet.verts.x, sheet.tris, nullptr, &sheet.verts.X, sigma, levels);
}

std::vector<Vec2> materialUvs(const std::vector<Vec2>& material) {
    if (material.empty()) return {};
    Vec2 lo = material.front(), hi = lo;
    for (const Vec2& X : material) {
        lo = lo.cwiseMin(X);
        hi = hi.cwiseMax(X);
    }
    Vec2 size = hi - lo;
    for (int k = 0; k < 2; ++k)
        if (!(size[k] > 0.0)) size[k] = 1.0; // a degenerate sheet: no stretching by 1/0
    std::vector<Vec2> uvs;
    uvs.reserve(material.size());
    for (const Vec2& X : material) uvs.push_back((X - lo).cwiseQuotient(size));
    return uvs;
}

SurfaceMesh subdivide(const std::vector<Vec3>& x, const std::vector<Triangle>& tris,
                      const std::vector<float>* scalars, const std::vector<Vec2>* material,
                      double sigma, int levels) {
    levels = std::clamp(levels, 0, kMaxSubdivisionLevel);
    SurfaceMesh mesh;
    mesh.positions = x;
    computeVertexNormals(x, tris, mesh.normals);
    if (scalars) mesh.scalars = *scalars;
    if (material && material->size() == x.size()) mesh.uvs = materialUvs(*material);
    mesh.triangles.reserve(tris.size());
    for (const Triangle& t : tris)
        mesh.triangles.push_back({static_cast<std::uint32_t>(t.v[0]),
                                  static_cast<std::uint32_t>(t.v[1]),
                                  static_cast<std::uint32_t>(t.v[2])});

    // Shared edges are found by sorting (edge key, corner) pairs rather than through a
    // hash map: a map allocates a node per edge, millions per second while the editor
    // plays, and that churn fragmented the heap enough to keep 25 MB after File ▸ New.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> corners;
    std::vector<std::uint32_t> midpointOfCorner;
    std::vector<std::array<std::uint32_t, 3>> next;
    for (int level = 0; level < levels; ++level) {
        const std::size_t nTris = mesh.triangles.size();
        corners.resize(3 * nTris);
        for (std::size_t t = 0; t < nTris; ++t)
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t a = mesh.triangles[t][e];
                const std::uint32_t b = mesh.triangles[t][(e + 1) % 3];
                corners[3 * t + e] = {(static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                                          std::max(a, b),
                                      static_cast<std::uint32_t>(3 * t + e)};
            }
        std::sort(corners.begin(), corners.end());
        midpointOfCorner.resize(3 * nTris);
        for (std::size_t i = 0; i < corners.size();) {
            const std::uint64_t key = corners[i].first;
            const auto a = static_cast<std::uint32_t>(key >> 32);
            const auto b = static_cast<std::uint32_t>(key & 0xffffffffu);
            const auto m = static_cast<std::uint32_t>(mesh.positions.size());
            mesh.positions.push_back(hermiteMidpoint(mesh.positions[a], mesh.positions[b],
                                                     mesh.normals[a], mesh.normals[b], sigma));
            mesh.normals.push_back(midpointNormal(mesh.normals[a], mesh.normals[b]));
            if (!mesh.scalars.empty())
                mesh.scalars.push_back(0.5f * (mesh.scalars[a] + mesh.scalars[b]));
            if (!mesh.uvs.empty()) mesh.uvs.push_back(0.5 * (mesh.uvs[a] + mesh.uvs[b]));
            for (; i < corners.size() && corners[i].first == key; ++i)
                midpointOfCorner[corners[i].second] = m;
        }
        next.clear();
        next.reserve(4 * nTris);
        for (std::size_t t = 0; t < nTris; ++t) {
            const auto& tri = mesh.triangles[t];
            const std::uint32_t mij = midpointOfCorner[3 * t];
            const std::uint32_t mjk = midpointOfCorner[3 * t + 1];
            const std::uint32_t mki = midpointOfCorner[3 * t + 2];
            // The four children of the paper's DrawTriangle, orientation kept.
            next.push_back({tri[0], mij, mki});
            next.push_back({mij, tri[1], mjk});
            next.push_back({mij, mjk, mki});
            next.push_back({mjk, tri[2], mki});
        }
        mesh.triangles.swap(next);
    }
    return mesh;
}

int subdivisionWithin(int requested, std::size_t triangles, std::size_t maxTriangles) {
    int level = 0;
    while (level < requested && (triangles << (2 * (level + 1))) <= maxTriangles) ++level;
    return level;
}

} // namespace pf
