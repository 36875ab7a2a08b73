#pragma once

#include "Camera.h"
#include "SheetSnapshot.h"

#include <optional>

namespace pf {

struct PickHit {
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitY(); // faces the ray's origin
    double distance = 0.0;       // along the ray
    bool onSheet = false;        // false: the ground plane was hit instead
};

// Where a ray first meets the sheet (its simulation triangles), or else the ground
// plane; nullopt if it meets neither.
std::optional<PickHit> pickSheet(const SheetSnapshot& snapshot, const OrbitCamera::Ray& ray);

// Half the length of each arm of the cross that marks a pin (m).
inline constexpr double kPinMarkArm = 0.003;

// The pinned vertex whose mark the ray passes through, or passes within `spread` radians
// of as seen from the eye, nearest the eye; none if it passes none. A pin at the paper's
// corner or edge has half its mark beyond the paper, where the ray meets only the desk
// or the sky: a click there, on the red cross, did nothing.
std::optional<Index> pinMarkOnRay(const SheetSnapshot& snapshot, const OrbitCamera::Ray& ray,
                                  double spread);

// Where the tool's centre goes for a pick: resting on the surface along the normal,
// or pushed `depth` into it.
Vec3 toolCenter(const PickHit& hit, double radius, double depth);

// Where the hovering tool's centre goes for a pick: resting on the surface along the
// normal, as toolCenter, then moved back along the ray toward the eye until no paper
// lies within its radius (by at most three radii). Over a folded sheet the sphere
// resting on one layer went 12 mm into the other, seen from the editor's view.
Vec3 restingToolCenter(const SheetSnapshot& snapshot, const OrbitCamera::Ray& ray,
                       const PickHit& hit, double radius);

} // namespace pf
