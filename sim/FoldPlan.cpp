#include "FoldPlan.h"

#include "Normals.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace pf {

namespace {

// How far the flap may dip below the ground on its way round: a sheet lying on the desk
// sits on it within the contact's tolerance.
constexpr double kDeskTolerance = 0.001; // m
// The carry is checked against the desk at this many angles along the way.
constexpr int kDeskChecks = 32;
// The paper's plane along the line is read from its normals this close to the segment.
constexpr double kFacingReach = 0.02; // m
// The paper along the line lies in a plane when its vertices spread across it less
// than this share of their spread along the second direction.
constexpr double kPlanarity = 0.1;
// The rise is checked against the paper held this far beyond the band on each side, at
// this many angles; below this weight of sin(θ/2) it comes as θ² alone.
constexpr double kRiseReach = 0.015; // m
constexpr int kRiseChecks = 16;
constexpr double kEarliestRise = 0.05;

} // namespace

FoldPlan planFold(const World& world, const FoldRequest& request) {
    FoldPlan plan;
    auto refuse = [&](FoldRefusal why) {
        plan.refusal = why;
        return plan;
    };
    if (!(request.angle > 0.0 && request.angle <= std::numbers::pi))
        return refuse(FoldRefusal::BadAngle);
    const Vec3 line = request.to - request.from;
    if (!(line.norm() >= kMinFoldLine)) return refuse(FoldRefusal::ShortLine);
    const Sheet& sheet = world.sheet;
    const auto& V = sheet.verts;

    // The paper along the line: the vertices within kFacingReach of the segment.
    std::vector<Vec3> normals;
    computeVertexNormals(sheet, normals);
    const Vec3 along = line.normalized();
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    std::vector<Index> near;
    Vec3 centre = Vec3::Zero();
    for (Index i = 0; i < V.size(); ++i) {
        const Vec3 r = V.x[i] - request.from;
        const double t = r.dot(along);
        if (t < -kFacingReach || t > line.norm() + kFacingReach) continue;
        if ((r - t * along).norm() > kFacingReach) continue;
        const Vec3& n = normals[static_cast<std::size_t>(i)];
        spread += n * n.transpose();
        near.push_back(i);
        centre += V.x[i];
    }
    if (near.empty() || !(spread.norm() > 0.0)) return refuse(FoldRefusal::OffSheet);
    centre /= static_cast<double>(near.size());
    // Which way the paper faces there (toward the viewer, `front`): the principal
    // direction of its normals, not their mean: where the paper already lies folded, its
    // layers face opposite ways and their normals cancel.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(spread);
    Vec3 front = principal.eigenvectors().col(2); // the largest eigenvalue's
    // The plane the paper lies in there: the least-squares plane through its vertices,
    // where they lie in one (the smallest spread across it, clearly). The axis must lie
    // in the paper along the whole line: the normals of a first fold's rounded crease
    // tilted their principal direction by 2.3 degrees, which put a second fold's axis
    // 14 mm off the paper at the far end of the line, and the carry stretched the paper
    // there by 81 % (8,500 % in the band that had to give).
    Eigen::Matrix3d positions = Eigen::Matrix3d::Zero();
    for (Index i : near) positions += (V.x[i] - centre) * (V.x[i] - centre).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> fit(positions);
    if (fit.eigenvalues()(0) < kPlanarity * fit.eigenvalues()(1)) front = fit.eigenvectors().col(0);
    const Vec3 viewer = request.viewer.norm() > 0.0 ? request.viewer : Vec3::UnitY();
    if (front.dot(viewer) < 0.0) front = -front;
    // The line in the paper's plane there, and the direction across it.
    Vec3 axis = along - along.dot(front) * front;
    if (!(axis.norm() > 1e-6)) return refuse(FoldRefusal::ShortLine); // drawn along the normal
    axis.normalize();
    const Vec3 across = front.cross(axis);
    // The line the flap turns about: the drawn one, moved onto the paper's plane.
    const Vec3 onPaper = request.from - (request.from - centre).dot(front) * front;

    // The flap is the lighter side: a hand folds the flap over, not the sheet under it.
    // But pinned paper stays where it is, so a side with pins is not the flap: carried
    // with pins in it, the flap tore from them (a valley fold past six pins: 25.8 %
    // stretch, 608 breaks, and 489 a second after the let-go).
    double mass[2] = {0.0, 0.0};
    bool pinnedOn[2] = {false, false};
    for (Index i = 0; i < V.size(); ++i) {
        const double d = (V.x[i] - onPaper).dot(across);
        mass[d > 0.0 ? 1 : 0] += V.m[i];
        if (V.pinned[i] && std::abs(d) > kPinOnLine) pinnedOn[d > 0.0 ? 1 : 0] = true;
    }
    if (!(mass[0] > 0.0 && mass[1] > 0.0)) return refuse(FoldRefusal::NothingToFold);
    if (pinnedOn[0] && pinnedOn[1]) return refuse(FoldRefusal::PinnedBothSides);
    // Halves that weigh the same (a line across the middle of a sheet) differ only by
    // rounding, which would pick the side by the sheet's resolution: within a billionth,
    // the side `across` points to is the flap.
    double side = mass[1] <= mass[0] * (1.0 + 1e-9) ? 1.0 : -1.0;
    if (pinnedOn[0] || pinnedOn[1]) side = pinnedOn[1] ? -1.0 : 1.0;
    // Toward the side the flap goes to: the front for a valley fold, the back for a
    // mountain fold.
    const double toward = request.mountain ? -1.0 : 1.0;
    const Vec3 up = toward * front;
    // What may be held: paper farther than the band from the line, and off the paper's
    // plane by at most kHeldSlope of that distance. Turning paper about a line it does
    // not lie in moves it away from the line: held on both sides, the paper between
    // would have to stretch, by about half the square of the slope (docs/model.md).
    // How far vertex i lies from the line, on the flap's side (sign 1) or the other.
    const auto beyond = [&](Index i, double sign) {
        return sign * side * (V.x[i] - onPaper).dot(across);
    };
    const auto holdable = [&](Index i, double sign) {
        const double d = beyond(i, sign);
        return d > kFoldBand && std::abs((V.x[i] - onPaper).dot(front)) <= kHeldSlope * d &&
               !V.pinned[i];
    };
    PinGroup carry;
    for (Index i = 0; i < V.size(); ++i) {
        if (holdable(i, 1.0)) {
            carry.vertices.push_back(i);
        } else if (beyond(i, 1.0) > kFoldBand && !V.pinned[i]) {
            plan.leftOut.vertices.push_back(i);
            plan.leftOut.atStart.push_back(V.x[i]);
        }
    }
    if (carry.vertices.empty()) return refuse(FoldRefusal::NothingToFold);
    plan.leftOut.pivot = onPaper;
    // Turning about side·axis carries the flap toward the front (axis × across = front).
    carry.axis = toward * side * axis;
    // The flap lands on the rest this far off the paper's plane: above the highest paper
    // along the line by 2 kFoldLift, so that the layers lie a paper's crumple apart.
    double highest = 0.0;
    for (Index i : near) {
        const double off = (V.x[i] - onPaper).dot(up);
        if (std::abs(off) <= kHeldSlope * std::max(std::abs(beyond(i, 1.0)), kFoldBand))
            highest = std::max(highest, off);
    }
    FoldPath path{onPaper, carry.axis, up, 2.0 * (highest + kFoldLift), 1.0};
    // How early the flap may rise: the earlier, the rounder the band while the flap goes
    // round (turned about a line through a row of vertices with the rise coming as θ², a
    // fold along the editor's sheet bent the band at that row alone: it ended with
    // 590-602 vertices and read 28 % stretch; with sin(θ/2), 507-509 and 0.3 %; 508 and
    // 0.5 % when the carry turned 3 mm off the paper). But it must not ask
    // the paper across the line to stretch: over the paper held on both sides near the
    // band, the largest stretch the pins alone would ask is checked at kRiseChecks
    // angles, and the earliest rise that asks at most half what the held slope may is taken
    // (or, if none does, the one that asks least).
    {
        const auto nearBand = [&](Index i, double sign) {
            return holdable(i, sign) && beyond(i, sign) < kFoldBand + kRiseReach;
        };
        std::vector<Index> flapNear, restNear;
        for (Index i = 0; i < V.size(); ++i) {
            if (nearBand(i, 1.0)) flapNear.push_back(i);
            if (nearBand(i, -1.0)) restNear.push_back(i);
        }
        const auto asked = [&](const FoldPath& p) {
            double worst = 0.0;
            for (int k = 1; k <= kRiseChecks; ++k) {
                const double theta = std::numbers::pi * k / kRiseChecks;
                for (Index c : flapNear) {
                    const Vec3 at = p.at(V.x[c], theta);
                    for (Index r : restNear) {
                        const double apart = sheet.materialDistance(c, r);
                        if (apart > 2.0 * (kFoldBand + kRiseReach)) continue;
                        // Paper already stretched (soft springs) is not asked for more.
                        const double was = std::max(apart, (V.x[c] - V.x[r]).norm());
                        worst = std::max(worst, (at - V.x[r]).norm() / was - 1.0);
                    }
                }
            }
            return worst;
        };
        const double allowed = 0.25 * kHeldSlope * kHeldSlope; // half the held slope's
        // Where none is within that (soft paper that a first fold left stretched and
        // rumpled), the one that asks least.
        double best = std::numeric_limits<double>::infinity(), bestEarly = 0.0;
        for (double early = 1.0;; early *= 0.5) {
            path.early = early > kEarliestRise ? early : 0.0;
            const double ask = asked(path);
            if (ask < best) {
                best = ask;
                bestEarly = path.early;
            }
            if (ask <= allowed || path.early == 0.0) break;
        }
        path.early = bestEarly;
    }

    // The lowest point the flap reaches on its way round.
    double lowestOnTheWay = std::numeric_limits<double>::infinity();
    for (int k = 1; k <= kDeskChecks; ++k)
        for (Index i : carry.vertices)
            lowestOnTheWay =
                std::min(lowestOnTheWay, path.at(V.x[i], std::numbers::pi * k / kDeskChecks).y());
    // The rest of the sheet is held where it lies, as the other hand holds it while one
    // folds: left free, the carry dragged it round, and a second fold across the first
    // ended with its layers turned 1.5-19.8 degrees apart in nine folds (docs/model.md,
    // "The Fold tool").
    PinGroup rest;
    for (Index i = 0; i < V.size(); ++i)
        if (holdable(i, -1.0)) rest.vertices.push_back(i);
    // A flap that would pass through the desk (a mountain fold of paper lying face up)
    // is folded as a hand folds it under: the sheet is lifted off the desk first, by as
    // much as the flap needs, and put down again once folded.
    double lift = 0.0;
    if (world.groundEnabled && lowestOnTheWay < world.groundHeight - kDeskTolerance) {
        lift = world.groundHeight + kDeskTolerance - lowestOnTheWay;
        // Pins hold the paper down: it cannot be lifted.
        for (Index i = 0; i < V.size(); ++i)
            if (V.pinned[i]) return refuse(FoldRefusal::DeskInTheWay);
        if (rest.vertices.empty()) return refuse(FoldRefusal::DeskInTheWay);
    }

    // Whole steps of motion; the times fall half a step off the step boundaries so that
    // the clock's rounding cannot move them by a step.
    const double h = world.params.dt;
    std::vector<PinGroup>& motions = plan.motions;
    auto stepsFor = [&](double seconds) { return std::max(1.0, std::ceil(seconds / h)); };
    // The carry from angle `from` to `to`, in kCarrySegments parts per half turn, each a
    // turn about the line the path turns about at its middle.
    auto turnBy = [&](const PinGroup& g, double from, double to, double t0, const Vec3& raised) {
        const double steps = stepsFor(std::abs(to - from) / kFoldTurnRate);
        const int parts = std::max(
            1,
            static_cast<int>(std::ceil(kCarrySegments * std::abs(to - from) / std::numbers::pi)));
        double done = 0.0;
        for (int k = 0; k < parts; ++k) {
            // Whole steps per part, the half turn's steps shared out among them.
            const double partSteps = std::floor(steps * (k + 1) / parts) - done;
            if (partSteps <= 0.0) continue;
            const double a = from + (to - from) * done / steps;
            const double b = from + (to - from) * (done + partSteps) / steps;
            PinGroup part = g;
            part.pivot = path.pivotAt(0.5 * (a + b)) + raised;
            part.turnRate = (b - a) / (partSteps * h);
            part.velocity.setZero();
            part.start = t0 + done * h;
            part.until = t0 + (done + partSteps) * h;
            motions.push_back(part);
            done += partSteps;
        }
        return t0 + steps * h;
    };
    auto move = [&](PinGroup g, const Vec3& by, double from) {
        const double steps = stepsFor(kFoldLiftSeconds);
        g.turnRate = 0.0;
        g.velocity = by / (steps * h);
        g.start = from;
        g.until = from + steps * h;
        return g;
    };
    double t = world.time - 0.5 * h;
    const Vec3 raised = lift * Vec3::UnitY();
    if (lift > 0.0) {
        motions.push_back(move(carry, raised, t));
        motions.push_back(move(rest, raised, t));
        t = motions.back().until;
    }
    t = turnBy(carry, 0.0, std::numbers::pi, t, raised) + kFoldPress;
    if (request.angle < std::numbers::pi)
        t = turnBy(carry, std::numbers::pi, request.angle, t, raised) + kFoldHold;
    if (lift > 0.0) {
        // Down onto the desk: by as much as the lowest paper then lies above it.
        double lowest = std::numeric_limits<double>::infinity();
        for (Index i : carry.vertices)
            lowest = std::min(lowest, path.at(V.x[i], request.angle).y() + lift);
        for (Index i : rest.vertices) lowest = std::min(lowest, V.x[i].y() + lift);
        const Vec3 down =
            -std::max(0.0, lowest - world.groundHeight - kDeskTolerance) * Vec3::UnitY();
        motions.push_back(move(carry, down, t));
        motions.push_back(move(rest, down, t));
        t = motions.back().until;
    }
    // Not lifted, the rest is held still throughout (lifted, it is held by its lift).
    if (lift == 0.0 && !rest.vertices.empty()) motions.push_back(rest);
    for (PinGroup& g : motions) g.release = t;
    plan.release = t;
    return plan;
}

} // namespace pf
