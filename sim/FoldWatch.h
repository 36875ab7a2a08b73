#pragma once

#include "Sheet.h"

#include <optional>
#include <vector>

namespace pf {

// How far a fold's flap turns back once it is let go: the status bar used to say "the
// crease keeps it" at every let-go, while a third fold along the diagonal of a sheet
// folded twice sprang back 99° within a second.
class FoldWatch {
  public:
    // The flap lets go at `time`; it is read again this long after.
    static constexpr double kSeconds = 1.0;

    // `carried`: the axis the carry turned the flap about (right-handed, the way it went);
    // `angle`: the angle it was folded to (radians), which bounds how far it can turn back.
    void start(const Sheet& sheet, std::vector<Index> flap, const Vec3& carried, double angle,
               double time);
    // Another edit came first (the sheet it watched may be gone).
    void cancel() { flap_.clear(); }
    // Once kSeconds have passed: how far the flap has turned back about the carry's axis
    // since it was let go, in degrees (negative: on, further closed; the turn that best
    // carries its vertices' offsets across the axis), in (angle − 360° + 30°, angle +
    // 30°]; read once. Nothing for a flap that has no width across the axis (a single
    // row of vertices along the line), whose turn cannot be read from its own vertices.
    std::optional<double> check(const Sheet& sheet, double time);

  private:
    std::vector<Index> flap_;
    std::vector<Vec3> letGo_;
    Vec3 carried_ = Vec3::UnitX();
    double angle_ = 0.0;
    double due_ = 0.0;
};

} // namespace pf
