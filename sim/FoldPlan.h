#pragma once

#include "FoldWatch.h"
#include "SceneScript.h"
#include "World.h"

#include <cmath>
#include <numbers>

namespace pf {

// A fold along a line drawn across the sheet: the part on one side of the line (the
// flap: the lighter one, or the one without pins) is carried round the line toward the viewer (a
// valley fold: seen from there the crease is a valley) or away (a mountain fold), flat onto the
// rest, held there so that the crease is pressed, opened back to `angle` and let go, as a hand
// folds paper: a crease that was never pressed flat springs open. Where the flap would pass through
// the desk (a mountain fold of paper lying face up), the sheet is lifted off it first and put down
// again once folded. Meanwhile the rest of the sheet is held where it lies, as the other hand
// holds it. The paper must lie within 2 cm of the segment drawn; the fold is then along
// the whole straight line through it, as on paper. Nothing is rotated rigidly into place: the flap
// is carried as a hand carries it, and the crease forms in the band along the line, where the paper
// bends, through the model's own breaks and hinges (docs/model.md, "The Fold tool").
struct FoldRequest {
    Vec3 from = Vec3::Zero(), to = Vec3::Zero();
    double angle = std::numbers::pi; // radians, in (0, π]
    bool mountain = false;
    // Toward the one who folds (the editor's eye); zero: from above.
    Vec3 viewer = Vec3::UnitY();
};

enum class FoldRefusal : std::uint8_t {
    None,
    ShortLine,      // shorter than kMinFoldLine
    OffSheet,       // no paper along the line
    NothingToFold,  // no paper beyond the band on one side, or none on the other
    DeskInTheWay,   // the flap would pass through the ground, and pins hold the sheet down
    BadAngle,       // not in (0, π]
    Busy,           // another edit is under way (EditSession)
    PinnedBothSides // pins hold paper on both sides of the line: there is no flap to carry
};

struct FoldPlan {
    FoldRefusal refusal = FoldRefusal::None;
    // The motions, in this order (applyScript lets a later group take over): the lift of
    // the flap and of the rest of the sheet (when the desk is in the way), the carry
    // round by π, the opening back to the angle (below π), and the lowering back onto
    // the desk; or, when the sheet is not lifted, the rest of it held still, last. All
    // let go at `release`.
    std::vector<PinGroup> motions;
    double release = 0.0;
    // The paper on the flap's side, beyond the band, that the carry does not hold: off
    // the plane along the line (the upper or lower layers of a folded stack, a first
    // crease's loop). It goes round only if the paper it hangs on takes it (FoldWatch).
    FoldLeftOut leftOut;
};

// The carry turns at this rate: a half turn in 1.5 s, as a hand folds a sheet.
constexpr double kFoldTurnRate = std::numbers::pi / 1.5; // rad/s
// Held flat this long, so that the crease forms, and at the fold angle before it is let
// go.
constexpr double kFoldPress = 1.2; // s
constexpr double kFoldHold = 0.5;  // s
// The flap lands twice this far above the highest paper along the line, on the side it
// folds to: the two layers of a flat fold then lie a paper's crumple apart, not in each
// other.
constexpr double kFoldLift = 0.003; // m
// A fold that must lift the sheet off the desk lifts it, and puts it down, in this time.
constexpr double kFoldLiftSeconds = 0.5; // s
// Vertices closer to the line than this stay free: the crease forms there.
constexpr double kFoldBand = 0.01; // m
// A pin this close to the line is on it: the crease may run through it.
constexpr double kPinOnLine = 0.001;  // m
constexpr double kMinFoldLine = 0.01; // m
// Paper off the plane the fold turns in by more than this share of its distance from
// the line stays free too: held, it would be carried away from the line and stretch the
// paper between it and the line's other side by about half the square (0.3 %).
constexpr double kHeldSlope = 0.08;
// The carry is this many turns per half turn, each about where the path turns then.
constexpr int kCarrySegments = 8;

// The path of the flap: turned by θ about `axis` through `pivot`, a line in the paper's
// plane, and raised along `up` by rise·s(θ), s(0) = 0, s(π) = 1. Turned about a line the
// paper lies in, the flap never moves away from the rest of the paper: the distance of
// two points across the line only shrinks as it turns. The rise, which rounds the
// band and puts the flap on the rest rather than in it, must not outpace that: at
// distances d and d_r from the line it may start no faster than d_r/2 per radian. So
// s is a blend of sin(θ/2) (a start at rise/2 per radian, which rounds the band at
// once) and (1 − cos θ)/2 (a start as θ²), the first weighted `early` =
// min(1, kEarlyRise·kFoldBand / rise).
struct FoldPath {
    Vec3 pivot, axis, up;
    double rise = 0.0;  // m, at θ = π
    double early = 1.0; // the weight of sin(θ/2) in s
    double shareAt(double theta) const {
        return early * std::sin(0.5 * theta) + (1.0 - early) * 0.5 * (1.0 - std::cos(theta));
    }
    // Where the point x of the flat flap is at θ.
    Vec3 at(const Vec3& x, double theta) const {
        return pivot + Eigen::AngleAxisd(theta, axis) * (x - pivot) + rise * shareAt(theta) * up;
    }
    // The line the path turns about at θ (where it is at rest at that instant): the
    // pivot raised with the flap and moved across by d(rise s)/dθ.
    Vec3 pivotAt(double theta) const {
        const double slope =
            early * 0.5 * std::cos(0.5 * theta) + (1.0 - early) * 0.5 * std::sin(theta);
        return pivot + rise * shareAt(theta) * up + rise * slope * axis.cross(up);
    }
};

FoldPlan planFold(const World& world, const FoldRequest& request);

} // namespace pf
