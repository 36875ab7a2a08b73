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

// Where the tool's centre goes for a pick: resting on the surface along the normal,
// or pushed `depth` into it.
Vec3 toolCenter(const PickHit& hit, double radius, double depth);

} // namespace pf
