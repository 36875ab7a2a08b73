#pragma once

#include "Sheet.h"

#include <Eigen/Geometry>
#include <optional>
#include <vector>

namespace pf {

// How far a fold's flap turns back once it is let go: the status bar used to say "the
// crease keeps it" at every let-go, while a third fold along the diagonal of a sheet
// folded twice sprang back 115° within a second.
class FoldWatch {
  public:
    // The flap lets go at `time`; it is read again this long after.
    static constexpr double kSeconds = 1.0;

    // `carried`: the axis the carry turned the flap about (right-handed, the way it went).
    void start(const Sheet& sheet, std::vector<Index> flap, const Vec3& carried, double time);
    // Another edit came first (the sheet it watched may be gone).
    void cancel() { flap_.clear(); }
    // Once kSeconds have passed: how far the flap has turned back since it was let go, in
    // degrees, against the way it was carried (negative: on, further closed; the turn of
    // the rigid motion that fits its vertices best, about the carry's axis); read once.
    std::optional<double> check(const Sheet& sheet, double time);

  private:
    std::vector<Index> flap_;
    std::vector<Vec3> letGo_;
    Vec3 carried_ = Vec3::UnitX();
    double due_ = 0.0;
};

// The rotation of the rigid motion that best carries the points `from` onto `to`
// (least squares, Kabsch).
Eigen::AngleAxisd rigidTurn(const std::vector<Vec3>& from, const std::vector<Vec3>& to);

} // namespace pf
