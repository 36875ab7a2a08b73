#pragma once

#include "Sheet.h"
#include "Types.h"

namespace pf {

// How pins let the sheet turn as a rigid body: about its centre of mass when nothing
// holds it, about a pin (or pins at one point) in any direction, about the line
// through pins in a row; pins that span a plane hold it from turning at all.
struct Pivot {
    enum class Kind { Free, Point, Axis, Held } kind = Kind::Free;
    Vec3 point = Vec3::Zero();
    Vec3 axis = Vec3::Zero(); // unit, for Kind::Axis
};

inline constexpr double kPinsApart = 1e-6; // m: pins closer than this hold one point or line

// The pivot the sheet's pinned vertices make (where they are now).
Pivot pivotOf(const Vertices& verts);

} // namespace pf
