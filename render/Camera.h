#pragma once

#include "Types.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

namespace pf {

using Mat4 = Eigen::Matrix4d;

// An orbit camera around a target, y up: yaw turns about y (0 looks along -z from
// +z), pitch lifts the eye above the horizon. Angles in degrees, distance in metres.
struct OrbitCamera {
    Vec3 target = Vec3::Zero();
    double yaw = 35.0;
    double pitch = 35.0;
    double distance = 0.6;
    double fovY = 35.0;
    double nearPlane = 0.005;
    double farPlane = 50.0;

    Vec3 eye() const;
    Mat4 view() const;
    Mat4 projection(double aspect) const;

    void orbit(double dYaw, double dPitch);
    // Moves the target in the view plane by a fraction of the visible height.
    void pan(double dx, double dy);
    // factor < 1 moves closer.
    void zoom(double factor);
    // Keeps the target at or above `floor` and the eye kEyeAboveFloor above it, by
    // lifting the target and then the pitch: seen from under the desk, the desk hid the
    // paper and the pins' marks showed through it.
    static constexpr double kEyeAboveFloor = 0.005;
    // How far around the target the desk is drawn: it fades into the background from
    // 0.35 of this to all of it (ground.frag). 1 m at the editor's usual distances, farther
    // as the camera backs off, so that paper slid off anywhere lies on it.
    double deskReach() const { return std::max(1.0, 1.6 * distance); }
    // Within this of the target the desk is drawn at least half as itself.
    double deskShown() const { return 0.675 * deskReach(); }
    void keepAbove(double floor);
    // Sets the distance so that a sphere of `radius` around `center` fills the view.
    void fit(const Vec3& center, double radius, double aspect);
    // fit() around the bounding sphere of `points` (at least 5 cm across).
    void fitPoints(const std::vector<Vec3>& points, double aspect);

    // The world-space ray through a pixel (x right, y down, in a width × height view).
    struct Ray {
        Vec3 origin, direction;
    };
    Ray rayThroughPixel(double px, double py, int width, int height) const;
};

// Named views: "top", "front", "iso". Returns nullopt for another name.
std::optional<OrbitCamera> namedView(std::string_view name);

} // namespace pf
