#pragma once

#include "SceneScript.h"
#include "World.h"

#include <numbers>

namespace pf {

// A fold along a line drawn across the sheet: the part on one side of the line (the
// lighter one, the flap) is carried round the line toward the viewer (a valley fold: seen
// from there the crease is a valley) or away (a mountain fold), flat onto the rest,
// held there so that the crease is pressed, opened back to `angle` and let go, as a
// hand folds paper: a crease that was never pressed flat springs open. Where the flap
// would pass through the desk (a mountain fold of paper lying face up), the sheet is
// lifted off it first and put down again once folded. The paper must lie within 2 cm of
// the segment drawn; the fold is then along the whole straight line through it, as on
// paper. Nothing is rotated rigidly into
// place: the flap is carried as a hand carries it, and the crease forms in the band
// along the line, where the paper bends, through the model's own breaks and hinges
// (docs/model.md, "The Fold tool").
struct FoldRequest {
    Vec3 from = Vec3::Zero(), to = Vec3::Zero();
    double angle = std::numbers::pi; // radians, in (0, π]
    bool mountain = false;
    // Toward the one who folds (the editor's eye); zero: from above.
    Vec3 viewer = Vec3::UnitY();
};

enum class FoldRefusal : std::uint8_t {
    None,
    ShortLine,     // shorter than kMinFoldLine
    OffSheet,      // no paper along the line
    NothingToFold, // no paper beyond the band on one side, or none on the other
    DeskInTheWay,  // the flap would pass through the ground, and pins hold the sheet down
    BadAngle,      // not in (0, π]
    Busy           // another edit is under way (EditSession)
};

struct FoldPlan {
    FoldRefusal refusal = FoldRefusal::None;
    // The motions, in this order (applyScript lets a later group take over): the lift of
    // the flap and of the rest of the sheet (when the desk is in the way), the carry
    // round by π, the opening back to the angle (below π), and the lowering back onto
    // the desk. All let go at `release`.
    std::vector<PinGroup> motions;
    double release = 0.0;
};

// The carry turns at this rate: a half turn in 1.5 s, as a hand folds a sheet.
constexpr double kFoldTurnRate = std::numbers::pi / 1.5; // rad/s
// Held flat this long, so that the crease forms, and at the fold angle before it is let
// go.
constexpr double kFoldPress = 1.2; // s
constexpr double kFoldHold = 0.5;  // s
// The line the flap turns about lies this far off the paper, on the side it folds to:
// the two layers of a flat fold then lie a paper's crumple apart, not in each other.
constexpr double kFoldLift = 0.003; // m
// A fold that must lift the sheet off the desk lifts it, and puts it down, in this time.
constexpr double kFoldLiftSeconds = 0.5; // s
// Vertices closer to the line than this stay free: the crease forms there.
constexpr double kFoldBand = 0.01;    // m
constexpr double kMinFoldLine = 0.01; // m

FoldPlan planFold(const World& world, const FoldRequest& request);

} // namespace pf
