#include "Camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pf {

namespace {

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

} // namespace

Vec3 OrbitCamera::eye() const {
    const double y = radians(yaw), p = radians(pitch);
    return target +
           distance * Vec3(std::sin(y) * std::cos(p), std::sin(p), std::cos(y) * std::cos(p));
}

Mat4 OrbitCamera::view() const {
    const Vec3 e = eye();
    const Vec3 f = (target - e).normalized();
    // The screen's right is the horizontal that yaw turns (what f × y gives wherever that
    // is defined), taken from yaw itself: near the pole f × y vanishes, and a fixed
    // stand-in for it there left the view from above deaf to yaw (a user's horizontal
    // drag did nothing at pitch 89.9).
    const double y = radians(yaw);
    const Vec3 s(std::cos(y), 0.0, -std::sin(y));
    const Vec3 u = s.cross(f).normalized();
    Mat4 m = Mat4::Identity();
    m.block<1, 3>(0, 0) = s.transpose();
    m.block<1, 3>(1, 0) = u.transpose();
    m.block<1, 3>(2, 0) = -f.transpose();
    m(0, 3) = -s.dot(e);
    m(1, 3) = -u.dot(e);
    m(2, 3) = f.dot(e);
    return m;
}

Mat4 OrbitCamera::projection(double aspect) const {
    const double t = 1.0 / std::tan(radians(fovY) / 2.0);
    Mat4 m = Mat4::Zero();
    m(0, 0) = t / aspect;
    m(1, 1) = t;
    m(2, 2) = (farPlane + nearPlane) / (nearPlane - farPlane);
    m(2, 3) = 2.0 * farPlane * nearPlane / (nearPlane - farPlane);
    m(3, 2) = -1.0;
    return m;
}

void OrbitCamera::orbit(double dYaw, double dPitch) {
    yaw = std::fmod(yaw + dYaw, 360.0);
    pitch = std::clamp(pitch + dPitch, -89.9, 89.9);
}

void OrbitCamera::keepAbove(double floor) {
    target.y() = std::max(target.y(), floor);
    if (!(distance > 0.0)) return;
    const double lowest = floor + kEyeAboveFloor;
    if (eye().y() >= lowest) return;
    const double rise = std::clamp((lowest - target.y()) / distance, -1.0, 1.0);
    pitch = std::clamp(std::asin(rise) * 180.0 / std::numbers::pi, pitch, 89.9);
}

void OrbitCamera::pan(double dx, double dy) {
    const Mat4 v = view();
    const Vec3 right = v.block<1, 3>(0, 0).transpose();
    const Vec3 up = v.block<1, 3>(1, 0).transpose();
    const double visible = 2.0 * distance * std::tan(radians(fovY) / 2.0);
    target += visible * (dx * right + dy * up);
}

void OrbitCamera::zoom(double factor) {
    distance = std::clamp(distance * factor, 0.02, 20.0);
}

void OrbitCamera::fit(const Vec3& center, double radius, double aspect) {
    target = center;
    const double halfV = radians(fovY) / 2.0;
    const double halfH = std::atan(std::tan(halfV) * aspect);
    distance = 1.08 * radius / std::sin(std::min(halfV, halfH));
}

void OrbitCamera::fitPoints(const std::vector<Vec3>& points, double aspect) {
    if (points.empty()) return;
    Vec3 lo = points.front(), hi = lo;
    for (const Vec3& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    fit(0.5 * (lo + hi), std::max(0.5 * (hi - lo).norm(), 0.05), aspect);
}

OrbitCamera::Ray OrbitCamera::rayThroughPixel(double px, double py, int width, int height) const {
    const double aspect = static_cast<double>(width) / height;
    const double ndcX = 2.0 * px / width - 1.0;
    const double ndcY = 1.0 - 2.0 * py / height;
    const double t = std::tan(radians(fovY) / 2.0);
    const Mat4 v = view();
    const Vec3 right = v.block<1, 3>(0, 0).transpose();
    const Vec3 up = v.block<1, 3>(1, 0).transpose();
    const Vec3 forward = -v.block<1, 3>(2, 0).transpose();
    return {eye(), (forward + ndcX * t * aspect * right + ndcY * t * up).normalized()};
}

std::optional<OrbitCamera> namedView(std::string_view name) {
    OrbitCamera c;
    if (name == "iso") {
        c.yaw = 35.0;
        c.pitch = 35.0;
    } else if (name == "top") {
        c.yaw = 0.0;
        c.pitch = 89.9;
    } else if (name == "front") {
        c.yaw = 0.0;
        c.pitch = 12.0;
    } else {
        return std::nullopt;
    }
    return c;
}

} // namespace pf
