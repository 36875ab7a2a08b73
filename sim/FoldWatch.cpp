#include "FoldWatch.h"

#include <Eigen/SVD>
#include <numbers>

namespace pf {

void FoldWatch::start(const Sheet& sheet, std::vector<Index> flap, const Vec3& carried,
                      double time) {
    flap_ = std::move(flap);
    carried_ = carried.normalized();
    letGo_.clear();
    for (Index i : flap_) letGo_.push_back(sheet.verts.x[i]);
    due_ = time + kSeconds;
}

std::optional<double> FoldWatch::check(const Sheet& sheet, double time) {
    if (flap_.empty() || time < due_) return std::nullopt;
    std::vector<Vec3> now;
    for (Index i : flap_) {
        // Breaks only add vertices; what renumbers them (an undo) cancels the watch.
        if (i >= sheet.verts.size()) {
            cancel();
            return std::nullopt;
        }
        now.push_back(sheet.verts.x[i]);
    }
    const Eigen::AngleAxisd turn = rigidTurn(letGo_, now);
    cancel();
    return -turn.angle() * turn.axis().dot(carried_) * 180.0 / std::numbers::pi;
}

Eigen::AngleAxisd rigidTurn(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
    if (from.size() < 3 || from.size() != to.size()) return Eigen::AngleAxisd::Identity();
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    for (std::size_t k = 0; k < from.size(); ++k) {
        a += from[k];
        b += to[k];
    }
    a /= static_cast<double>(from.size());
    b /= static_cast<double>(to.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (std::size_t k = 0; k < from.size(); ++k)
        covariance += (from[k] - a) * (to[k] - b).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    // A proper rotation: a reflection fits a flat flap as well as a turn does.
    Eigen::Matrix3d sign = Eigen::Matrix3d::Identity();
    if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0) sign(2, 2) = -1.0;
    return Eigen::AngleAxisd(Eigen::Matrix3d(svd.matrixV() * sign * svd.matrixU().transpose()));
}

} // namespace pf
