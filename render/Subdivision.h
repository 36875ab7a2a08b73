#pragma once

#include "Sheet.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pf {

// Paper §4.3: the internal point of edge (i, j) on the Hermite curve through x_i, x_j
// whose end tangents are σ(x_j - x_i) projected onto the tangent planes of n_i, n_j:
//   m = (x_i + x_j)/2 + (C'(0) - C'(1))/8.
// The expression is symmetric in (i, j) to the last bit (it only uses sums, exact
// negations and commutative products), so neighbouring triangles share midpoints.
Vec3 hermiteMidpoint(const Vec3& xi, const Vec3& xj, const Vec3& ni, const Vec3& nj, double sigma);

// The normal carried to an internal point: the normalised mean of the end normals.
Vec3 midpointNormal(const Vec3& ni, const Vec3& nj);

// An indexed triangle surface with one normal per vertex.
struct SurfaceMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<float> scalars; // optional per-vertex value (a heat map), averaged at midpoints
    // Optional texture coordinates: the material coordinates scaled to 0..1 over the
    // sheet (materialUvs), u along the sheet's width (x), v along its length (z), with
    // the image's top-left corner (glTF's convention) at the sheet's (-x, -z) corner.
    // A midpoint takes the mean: the coordinate is affine in the material, so that is
    // the material midpoint's own coordinate.
    std::vector<Vec2> uvs;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

inline constexpr int kMaxSubdivisionLevel = 4;

// Subdivides every simulation triangle `levels` times (0..kMaxSubdivisionLevel),
// each time splitting it into four at the Hermite midpoints of its edges. A
// midpoint is made once per edge and shared by both triangles, so the surface
// has no cracks. Vertex normals start as the sheet's area-weighted normals.
// `scalars`, if not null, holds one value per vertex carried to the subdivided surface;
// `material`, if not null and one per vertex, the vertices' material coordinates,
// carried as uvs (the mesh has none otherwise).
SurfaceMesh subdivide(const std::vector<Vec3>& x, const std::vector<Triangle>& tris,
                      const std::vector<float>* scalars, const std::vector<Vec2>* material,
                      double sigma, int levels);
SurfaceMesh subdivideSheet(const Sheet& sheet, double sigma, int levels);

// A Hermite midpoint bulges past its edge, and at a fold lying on the desk below it
// (a mountain fold's crease, subdivided three times: 0.77 mm into the desk, 3.2 mm at
// σ = 4): paper cannot. Every point below the desk is put on it, in the pictures and in
// the exported meshes alike.
void liftOntoTheDesk(SurfaceMesh& mesh, double groundHeight);

// Material coordinates scaled to 0..1 over their bounding box, per axis (a sheet's
// material domain is its rectangle: inserted vertices lie on its edges).
std::vector<Vec2> materialUvs(const std::vector<Vec2>& material);

// The finest level up to `requested` at which `triangles` simulation triangles give at
// most `maxTriangles` surface triangles (each level has four times the one before);
// level 0 is always allowed.
int subdivisionWithin(int requested, std::size_t triangles, std::size_t maxTriangles);

} // namespace pf
