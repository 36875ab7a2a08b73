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

void liftOntoTheDesk(SurfaceMesh& mesh, double groundHeight) {
    for (Vec3& p : mesh.positions) p.y() = std::max(p.y(), groundHeight);
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

    // The corners of the triangles (corner e of triangle t, index 3t + e, is the edge
    // from its vertex e to vertex e + 1) that lie on one edge form a ring (`nextOnEdge`),
    // and each ring gets one midpoint. The rings of the simulation mesh are found by
    // sorting (edge key, corner) pairs once; a hash map allocated a node per edge,
    // millions per second while the editor played, and that churn fragmented the heap
    // enough to keep 25 MB after File ▸ New. Each later level's rings follow from the
    // level before (the two halves of an edge, and the three edges inside each
    // triangle), so no level after the first sorts: sorting was half of the time.
    const std::size_t firstTris = mesh.triangles.size();
    std::vector<std::uint32_t> nextOnEdge(3 * firstTris);
    if (levels > 0) {
        std::vector<std::pair<std::uint64_t, std::uint32_t>> corners(3 * firstTris);
        for (std::size_t t = 0; t < firstTris; ++t)
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t a = mesh.triangles[t][e];
                const std::uint32_t b = mesh.triangles[t][(e + 1) % 3];
                corners[3 * t + e] = {(static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                                          std::max(a, b),
                                      static_cast<std::uint32_t>(3 * t + e)};
            }
        std::sort(corners.begin(), corners.end());
        std::size_t edges = 0;
        for (std::size_t i = 0; i < corners.size(); ++edges) {
            std::size_t end = i;
            while (end < corners.size() && corners[end].first == corners[i].first) ++end;
            for (std::size_t k = i; k < end; ++k)
                nextOnEdge[corners[k].second] = corners[k + 1 < end ? k + 1 : i].second;
            i = end;
        }
        // Each level adds a vertex per edge; an edge becomes two, and each triangle adds
        // three inside. Reserved at once: grown level by level, the copies and the
        // fresh pages they touched cost a quarter of the time.
        std::size_t vertices = mesh.positions.size(), triangles = firstTris;
        for (int level = 0; level < levels; ++level) {
            vertices += edges;
            edges = 2 * edges + 3 * triangles;
            triangles *= 4;
        }
        mesh.positions.reserve(vertices);
        mesh.normals.reserve(vertices);
        if (!mesh.scalars.empty()) mesh.scalars.reserve(vertices);
        if (!mesh.uvs.empty()) mesh.uvs.reserve(vertices);
    }
    // Where the halves of a triangle's corner e go among its four children's corners
    // (child c's corner f is 3c + f): the half at the corner's first vertex, the half
    // at its second. The children are the paper's DrawTriangle's, orientation kept:
    // {v0, m01, m20}, {m01, v1, m12}, {m01, m12, m20}, {m12, v2, m20}.
    constexpr std::uint32_t kHalfAtStart[3] = {0, 4, 10};
    constexpr std::uint32_t kHalfAtEnd[3] = {3, 9, 2};
    // The edges inside a triangle, each shared by two of its children.
    constexpr std::uint32_t kInside[3][2] = {{1, 8}, {5, 6}, {7, 11}};
    constexpr std::uint32_t kUnmade = 0xffffffffu;
    std::vector<std::uint32_t> midpointOfCorner, nextChild;
    std::vector<std::array<std::uint32_t, 3>> next;
    for (int level = 0; level < levels; ++level) {
        const std::size_t nTris = mesh.triangles.size();
        const auto corner = [&](std::uint32_t c, int end) {
            return mesh.triangles[c / 3][(c % 3 + end) % 3];
        };
        // The child corners that are corner c's halves at vertex v and at its other end.
        const auto halves = [&](std::uint32_t c, std::uint32_t v) {
            const std::uint32_t t = c / 3, e = c % 3;
            return corner(c, 0) == v ? std::array<std::uint32_t, 2>{12 * t + kHalfAtStart[e],
                                                                    12 * t + kHalfAtEnd[e]}
                                     : std::array<std::uint32_t, 2>{12 * t + kHalfAtEnd[e],
                                                                    12 * t + kHalfAtStart[e]};
        };
        midpointOfCorner.assign(3 * nTris, kUnmade);
        const bool deeper = level + 1 < levels;
        if (deeper) nextChild.resize(12 * nTris);
        for (std::uint32_t c = 0; c < 3 * nTris; ++c) {
            if (midpointOfCorner[c] != kUnmade) continue;
            const std::uint32_t a = corner(c, 0), b = corner(c, 1);
            const auto m = static_cast<std::uint32_t>(mesh.positions.size());
            // The same expression as its neighbours', whichever end comes first: the
            // midpoint is symmetric to the last bit.
            mesh.positions.push_back(hermiteMidpoint(mesh.positions[a], mesh.positions[b],
                                                     mesh.normals[a], mesh.normals[b], sigma));
            mesh.normals.push_back(midpointNormal(mesh.normals[a], mesh.normals[b]));
            if (!mesh.scalars.empty())
                mesh.scalars.push_back(0.5f * (mesh.scalars[a] + mesh.scalars[b]));
            if (!mesh.uvs.empty()) mesh.uvs.push_back(0.5 * (mesh.uvs[a] + mesh.uvs[b]));
            // Around the ring: every corner on this edge takes the midpoint, and the
            // halves at vertex a (and those at b) of all of them form the next level's
            // rings, in the same order.
            std::uint32_t r = c;
            auto here = halves(c, a);
            do {
                midpointOfCorner[r] = m;
                if (deeper) {
                    const auto after = halves(nextOnEdge[r], a);
                    nextChild[here[0]] = after[0];
                    nextChild[here[1]] = after[1];
                    here = after;
                }
                r = nextOnEdge[r];
            } while (r != c);
        }
        next.clear();
        next.reserve(4 * nTris);
        for (std::size_t t = 0; t < nTris; ++t) {
            const auto& tri = mesh.triangles[t];
            const std::uint32_t mij = midpointOfCorner[3 * t];
            const std::uint32_t mjk = midpointOfCorner[3 * t + 1];
            const std::uint32_t mki = midpointOfCorner[3 * t + 2];
            next.push_back({tri[0], mij, mki});
            next.push_back({mij, tri[1], mjk});
            next.push_back({mij, mjk, mki});
            next.push_back({mjk, tri[2], mki});
            if (deeper)
                for (const auto& pair : kInside) {
                    nextChild[12 * t + pair[0]] = static_cast<std::uint32_t>(12 * t + pair[1]);
                    nextChild[12 * t + pair[1]] = static_cast<std::uint32_t>(12 * t + pair[0]);
                }
        }
        mesh.triangles.swap(next);
        if (deeper) nextOnEdge.swap(nextChild);
    }
    return mesh;
}

int subdivisionWithin(int requested, std::size_t triangles, std::size_t maxTriangles) {
    int level = 0;
    while (level < requested && (triangles << (2 * (level + 1))) <= maxTriangles) ++level;
    return level;
}

} // namespace pf
