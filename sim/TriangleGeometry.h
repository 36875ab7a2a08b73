#pragma once

#include "Types.h"

namespace pf {

// Barycentric coordinates of the point of triangle (a, b, c) closest to p (Ericson,
// Real-Time Collision Detection, 5.1.5).
Vec3 closestPointBarycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p);

// Barycentric coordinates of the foot of p on the plane of (a, b, c), unclamped; false
// for a triangle without area.
bool footBarycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p, Vec3& out);

} // namespace pf
