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

    // The paper's plane along the line: the principal direction of its normals there.
    // Not their mean: where the paper already lies folded, its layers face opposite ways
    // and their normals cancel. It faces the viewer (`front`).
    std::vector<Vec3> normals;
    computeVertexNormals(sheet, normals);
    const Vec3 along = line.normalized();
    Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
    int near = 0;
    for (Index i = 0; i < V.size(); ++i) {
        const Vec3 r = V.x[i] - request.from;
        const double t = r.dot(along);
        if (t < -kFacingReach || t > line.norm() + kFacingReach) continue;
        if ((r - t * along).norm() > kFacingReach) continue;
        const Vec3& n = normals[static_cast<std::size_t>(i)];
        spread += n * n.transpose();
        ++near;
    }
    if (near == 0 || !(spread.norm() > 0.0)) return refuse(FoldRefusal::OffSheet);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(spread);
    Vec3 front = principal.eigenvectors().col(2); // the largest eigenvalue's
    const Vec3 viewer = request.viewer.norm() > 0.0 ? request.viewer : Vec3::UnitY();
    if (front.dot(viewer) < 0.0) front = -front;
    // The line in the paper's plane there, and the direction across it.
    Vec3 axis = along - along.dot(front) * front;
    if (!(axis.norm() > 1e-6)) return refuse(FoldRefusal::ShortLine); // drawn along the normal
    axis.normalize();
    const Vec3 across = front.cross(axis);

    // The flap is the lighter side: a hand folds the flap over, not the sheet under it.
    double mass[2] = {0.0, 0.0};
    for (Index i = 0; i < V.size(); ++i)
        mass[(V.x[i] - request.from).dot(across) > 0.0 ? 1 : 0] += V.m[i];
    if (!(mass[0] > 0.0 && mass[1] > 0.0)) return refuse(FoldRefusal::NothingToFold);
    // Halves that weigh the same (a line across the middle of a sheet) differ only by
    // rounding, which would pick the side by the sheet's resolution: within a billionth,
    // the side `across` points to is the flap.
    const double side = mass[1] <= mass[0] * (1.0 + 1e-9) ? 1.0 : -1.0;
    PinGroup carry;
    for (Index i = 0; i < V.size(); ++i)
        if (side * (V.x[i] - request.from).dot(across) > kFoldBand && !V.pinned[i])
            carry.vertices.push_back(i);
    if (carry.vertices.empty()) return refuse(FoldRefusal::NothingToFold);

    // Turning about side·axis carries the flap toward the front (axis × across = front).
    const double toward = request.mountain ? -1.0 : 1.0;
    carry.axis = toward * side * axis;
    carry.pivot = request.from + toward * kFoldLift * front;
    // The lowest point the flap reaches on its way round, with the sheet raised by `lift`.
    auto lowestOnTheWay = [&](double lift) {
        double lowest = std::numeric_limits<double>::infinity();
        const Vec3 up = lift * Vec3::UnitY();
        for (int k = 1; k <= kDeskChecks; ++k) {
            const Eigen::AngleAxisd turn(std::numbers::pi * k / kDeskChecks, carry.axis);
            for (Index i : carry.vertices)
                lowest = std::min(lowest, (carry.pivot + turn * (V.x[i] - carry.pivot)).y());
        }
        return lowest + up.y();
    };
    // A flap that would pass through the desk (a mountain fold of paper lying face up)
    // is folded as a hand folds it under: the sheet is lifted off the desk first, by as
    // much as the flap needs, and put down again once folded.
    double lift = 0.0;
    PinGroup rest;
    if (world.groundEnabled && lowestOnTheWay(0.0) < world.groundHeight - kDeskTolerance) {
        lift = world.groundHeight + kDeskTolerance - lowestOnTheWay(0.0);
        for (Index i = 0; i < V.size(); ++i) {
            // Pins hold the paper down: it cannot be lifted.
            if (V.pinned[i]) return refuse(FoldRefusal::DeskInTheWay);
            if (side * (V.x[i] - request.from).dot(across) < -kFoldBand) rest.vertices.push_back(i);
        }
        if (rest.vertices.empty()) return refuse(FoldRefusal::DeskInTheWay);
    }

    // Whole steps of motion; the times fall half a step off the step boundaries so that
    // the clock's rounding cannot move them by a step.
    const double h = world.params.dt;
    auto stepsFor = [&](double seconds) { return std::max(1.0, std::ceil(seconds / h)); };
    auto turnBy = [&](PinGroup g, double angle, double from) {
        const double steps = stepsFor(std::abs(angle) / kFoldTurnRate);
        g.turnRate = angle / (steps * h);
        g.velocity.setZero();
        g.start = from;
        g.until = from + steps * h;
        return g;
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
    std::vector<PinGroup>& motions = plan.motions;
    const Vec3 up = lift * Vec3::UnitY();
    if (lift > 0.0) {
        motions.push_back(move(carry, up, t));
        motions.push_back(move(rest, up, t));
        t = motions.back().until;
        carry.pivot += up;
    }
    motions.push_back(turnBy(carry, std::numbers::pi, t));
    t = motions.back().until + kFoldPress;
    if (request.angle < std::numbers::pi) {
        motions.push_back(turnBy(carry, request.angle - std::numbers::pi, t));
        t = motions.back().until + kFoldHold;
    }
    if (lift > 0.0) {
        // Down onto the desk: by as much as the lowest paper then lies above it.
        const Eigen::AngleAxisd turned(request.angle, carry.axis);
        double lowest = std::numeric_limits<double>::infinity();
        for (Index i : carry.vertices)
            lowest = std::min(lowest, (carry.pivot + turned * (V.x[i] + up - carry.pivot)).y());
        for (Index i : rest.vertices) lowest = std::min(lowest, V.x[i].y() + lift);
        const Vec3 down =
            -std::max(0.0, lowest - world.groundHeight - kDeskTolerance) * Vec3::UnitY();
        motions.push_back(move(carry, down, t));
        motions.push_back(move(rest, down, t));
        t = motions.back().until;
    }
    for (PinGroup& g : motions) g.release = t;
    plan.release = t;
    return plan;
}

} // namespace pf
