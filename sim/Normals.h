#pragma once

#include "Sheet.h"

#include <vector>

namespace pf {

// Area-weighted vertex normals: the sum of the (unnormalised) cross products of
// the incident triangles, normalised. A vertex with no area gets +y.
void computeVertexNormals(const Sheet& sheet, std::vector<Vec3>& normals);
void computeVertexNormals(const std::vector<Vec3>& x, const std::vector<Triangle>& tris,
                          std::vector<Vec3>& normals);

} // namespace pf
