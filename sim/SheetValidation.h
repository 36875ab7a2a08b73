#pragma once

#include "Sheet.h"

#include <string>

namespace pf {

// Checks that a sheet is a consistent triangle mesh with springs: array sizes agree,
// every index is in range, numbers are finite and coordinates within 10 km, triangles are
// non-degenerate in material space, every triangle edge is a structural spring that lists the
// triangle as a face and vice versa, every vertex belongs to a triangle, and active log events
// point at real elements. Returns an empty string if valid, else the first problem.
std::string validateSheet(const Sheet& sheet);

// V - E + F with E the structural springs (the triangle edges).
long eulerCharacteristic(const Sheet& sheet);

} // namespace pf
