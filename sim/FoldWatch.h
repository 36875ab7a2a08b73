#pragma once

#include "Sheet.h"

#include <optional>
#include <vector>

namespace pf {

// The paper on the flap's side that the carry does not hold, where it was when the
// fold began, and a point of the line the flap turns about.
struct FoldLeftOut {
    std::vector<Index> vertices;
    std::vector<Vec3> atStart;
    Vec3 pivot = Vec3::Zero();
};

// How far a fold's flap turns back once it is let go: the status bar used to say "the
// crease keeps it" at every let-go, while a third fold along the diagonal of a sheet
// folded twice sprang back 99° within a second. And whether the paper on the flap's
// side that the carry did not hold went with it: the carry holds only paper lying in
// the plane along the line (FoldPlan), so of a stack folded twice a third fold across
// it carried the upper layers over and left the lower ones lying flat, while the
// status bar said "Folded.".
class FoldWatch {
  public:
    // The flap lets go at `time`; it is read again this long after.
    static constexpr double kSeconds = 1.0;

    // (Declared outside the class: a default argument cannot use the initialisers of a
    // class nested in one not yet complete.)
    using LeftOut = FoldLeftOut;

    struct Reading {
        // How far the flap has turned back about the carry's axis since it was let go,
        // against the rest of the sheet, in degrees (negative: on, further closed; the
        // turn that best carries its vertices' offsets across the axis, less the rest's),
        // in (angle − 360° + 30°, angle + 30°]. Read against the rest because a fold is
        // the angle between the two: a folded sheet that rolls over as a whole has not
        // opened, and one whose lower part turned over while the flap lay still has (in
        // an editor session a stack fell open that way while the status bar said
        // "Folded."). Where the rest has no width across the axis, the flap's own turn.
        // Nothing for a flap that has no width across the axis (a single row of vertices
        // along the line), whose turn cannot be read from its own vertices.
        std::optional<double> turnedBack;
        // The share of the paper on the flap's side (by vertices) that the carry left out
        // and that lies unfolded: each such vertex turned about the line by less than
        // half the fold's angle since the fold began. It was never carried round, or it
        // was dragged round and fell back open at the let-go (an editor session filmed
        // both). 0 if all of it is folded or none was left out.
        double unfoldedShare = 0.0;
    };

    // `carried`: the axis the carry turned the flap about (right-handed, the way it went);
    // `angle`: the angle it was folded to (radians), which bounds how far it can turn back;
    // `left`: the paper the carry did not hold, as it lay when the fold began.
    void start(const Sheet& sheet, std::vector<Index> flap, const Vec3& carried, double angle,
               double time, LeftOut left = {});
    // Another edit came first (the sheet it watched may be gone).
    void cancel() {
        flap_.clear();
        rest_.clear();
        left_ = {};
    }

    // Once kSeconds have passed, read once; nothing if there is nothing to read.
    std::optional<Reading> check(const Sheet& sheet, double time);
    // Before then: true once, at the first step the flap has turned back more than `past`
    // degrees. A 90° fold could lie flat again for most of the second while the status bar
    // still said "Folded."; the reading at kSeconds says how far it went.
    bool openingEarly(const Sheet& sheet, double time, double past);

  private:
    // How far the flap has turned back against the rest (Reading::turnedBack); nothing if
    // its turn cannot be read or the sheet lost the vertices.
    std::optional<double> turnedBack(const Sheet& sheet) const;

    std::vector<Index> flap_;
    std::vector<Vec3> letGo_;
    // The rest of the sheet (neither the flap nor paper left out), where it lay at the
    // let-go.
    std::vector<Index> rest_;
    std::vector<Vec3> restLetGo_;
    LeftOut left_;
    Vec3 carried_ = Vec3::UnitX();
    double angle_ = 0.0;
    double due_ = 0.0;
    bool saidOpening_ = false;
};

} // namespace pf
