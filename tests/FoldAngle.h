#pragma once

#include "Sheet.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pf {

// The angle a sheet is folded by about the line across its middle, in degrees: 0 flat,
// 180 folded flat onto itself. Measured between the centres of the strips a quarter of
// the length to either side of the fold, seen from the fold line's centre (material
// coordinates say which vertices those are, however the sheet has moved).
inline double foldAngle(const Sheet& s, double length) {
    const double band = 0.02;
    Vec3 sum[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    int count[3] = {0, 0, 0};
    for (Index i = 0; i < s.verts.size(); ++i) {
        const double along = s.verts.X[i].y();
        for (int k = 0; k < 3; ++k) {
            const double centre = (k - 1) * 0.25 * length;
            if (std::abs(along - centre) <= band) {
                sum[k] += s.verts.x[i];
                ++count[k];
            }
        }
    }
    const Vec3 fold = sum[1] / count[1];
    const Vec3 nearSide = sum[0] / count[0] - fold, farSide = sum[2] / count[2] - fold;
    const double opening =
        std::acos(std::clamp(nearSide.normalized().dot(farSide.normalized()), -1.0, 1.0));
    return 180.0 - opening * 180.0 / std::numbers::pi;
}

} // namespace pf
