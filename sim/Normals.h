#pragma once

#include "Sheet.h"
#include "VertexStars.h"
#include "WorkerPool.h"

#include <vector>

namespace pf {

// Area-weighted vertex normals: the sum of the (unnormalised) cross products of
// the incident triangles, normalised. A vertex with no area gets +y.
void computeVertexNormals(const Sheet& sheet, std::vector<Vec3>& normals);
void computeVertexNormals(const std::vector<Vec3>& x, const std::vector<Triangle>& tris,
                          std::vector<Vec3>& normals);
// The same normals, bit for bit, on the pool's threads: each triangle's cross product into
// triangleNormals, then each vertex sums its star's in the order the loop above adds them.
void computeVertexNormals(const Sheet& sheet, std::vector<Vec3>& normals, WorkerPool& pool,
                          const VertexStars& stars, std::vector<Vec3>& triangleNormals);

} // namespace pf
