#include "Subdivision.h"

#include "Normals.h"

#include <algorithm>
#include <unordered_map>

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
    return subdivide(sheet.verts.x, sheet.tris, nullptr, sigma, levels);
}

SurfaceMesh subdivide(const std::vector<Vec3>& x, const std::vector<Triangle>& tris,
                      const std::vector<float>* scalars, double sigma, int levels) {
    levels = std::clamp(levels, 0, kMaxSubdivisionLevel);
    SurfaceMesh mesh;
    mesh.positions = x;
    computeVertexNormals(x, tris, mesh.normals);
    if (scalars) mesh.scalars = *scalars;
    mesh.triangles.reserve(tris.size());
    for (const Triangle& t : tris)
        mesh.triangles.push_back({static_cast<std::uint32_t>(t.v[0]),
                                  static_cast<std::uint32_t>(t.v[1]),
                                  static_cast<std::uint32_t>(t.v[2])});

    std::unordered_map<std::uint64_t, std::uint32_t> midpointOf;
    std::vector<std::array<std::uint32_t, 3>> next;
    for (int level = 0; level < levels; ++level) {
        midpointOf.clear();
        midpointOf.reserve(mesh.triangles.size() * 2);
        next.clear();
        next.reserve(mesh.triangles.size() * 4);
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint64_t key =
                (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
            auto [it, inserted] =
                midpointOf.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
            if (inserted) {
                const Vec3 p = hermiteMidpoint(mesh.positions[a], mesh.positions[b],
                                               mesh.normals[a], mesh.normals[b], sigma);
                const Vec3 n = midpointNormal(mesh.normals[a], mesh.normals[b]);
                mesh.positions.push_back(p);
                mesh.normals.push_back(n);
                if (!mesh.scalars.empty())
                    mesh.scalars.push_back(0.5f * (mesh.scalars[a] + mesh.scalars[b]));
            }
            return it->second;
        };
        for (const auto& t : mesh.triangles) {
            const std::uint32_t mij = midpoint(t[0], t[1]);
            const std::uint32_t mjk = midpoint(t[1], t[2]);
            const std::uint32_t mki = midpoint(t[2], t[0]);
            // The four children of the paper's DrawTriangle, orientation kept.
            next.push_back({t[0], mij, mki});
            next.push_back({mij, t[1], mjk});
            next.push_back({mij, mjk, mki});
            next.push_back({mjk, t[2], mki});
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
