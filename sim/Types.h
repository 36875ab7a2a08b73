#pragma once

#include <Eigen/Dense>
#include <cstdint>

namespace pf {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// 32-bit ids keep the hot arrays small; a sheet never approaches 2^31 elements.
using Index = std::int32_t;
inline constexpr Index kNone = -1;

} // namespace pf
