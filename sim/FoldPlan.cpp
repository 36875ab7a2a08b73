#include "FoldPlan.h"

#include "Normals.h"

#include <cmath>

namespace pf {

namespace {

// How far the flap may dip below the ground on its way round: a sheet lying on the desk
// sits on it within the contact's tolerance.
constexpr double kDeskTolerance = 0.001; // m
// The carry is checked against the desk at this many angles along the way.
constexpr int kDeskChecks = 32;
// The paper's facing along the line is the mean of its normals this close to the line.
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

    // Which way the paper's front faces along the line (its normals follow the
    // triangles' winding, so they tell front from back however the sheet lies).
    std::vector<Vec3> normals;
    computeVertexNormals(sheet, normals);
    const Vec3 along = line.normalized();
    Vec3 front = Vec3::Zero();
    for (Index i = 0; i < V.size(); ++i) {
        const Vec3 r = V.x[i] - request.from;
        const double t = r.dot(along);
        if (t < -kFacingReach || t > line.norm() + kFacingReach) continue;
        if ((r - t * along).norm() <= kFacingReach) front += normals[static_cast<std::size_t>(i)];
    }
    if (!(front.norm() > 0.0)) return refuse(FoldRefusal::OffSheet);
    front.normalize();
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
    const double side = mass[1] <= mass[0] ? 1.0 : -1.0;
    PinGroup carry;
    for (Index i = 0; i < V.size(); ++i)
        if (side * (V.x[i] - request.from).dot(across) > kFoldBand && !V.pinned[i])
            carry.vertices.push_back(i);
    if (carry.vertices.empty()) return refuse(FoldRefusal::NothingToFold);

    // Turning about side·axis carries the flap toward the front (axis × across = front).
    const double toward = request.mountain ? -1.0 : 1.0;
    carry.axis = toward * side * axis;
    carry.pivot = request.from + toward * kFoldLift * front;
    if (world.groundEnabled) {
        for (int k = 1; k <= kDeskChecks; ++k) {
            const Eigen::AngleAxisd turn(std::numbers::pi * k / kDeskChecks, carry.axis);
            for (Index i : carry.vertices) {
                const Vec3 at = carry.pivot + turn * (V.x[i] - carry.pivot);
                if (at.y() < world.groundHeight - kDeskTolerance)
                    return refuse(FoldRefusal::DeskInTheWay);
            }
        }
    }

    // Whole steps of turning that end exactly at the angle; the times fall half a step
    // off the step boundaries so that the clock's rounding cannot move them by a step.
    const double h = world.params.dt;
    auto turnBy = [&](PinGroup& g, double angle, double from) {
        const double steps = std::max(1.0, std::ceil(std::abs(angle) / (kFoldTurnRate * h)));
        g.turnRate = angle / (steps * h);
        g.start = from;
        g.until = from + steps * h;
    };
    const double now = world.time - 0.5 * h;
    turnBy(carry, std::numbers::pi, now);
    double end = carry.until + kFoldPress;
    if (request.angle < std::numbers::pi) {
        PinGroup opening = carry;
        turnBy(opening, request.angle - std::numbers::pi, end);
        end = opening.until + kFoldHold;
        plan.motions.push_back(carry);
        plan.motions.push_back(opening);
    } else {
        plan.motions.push_back(carry);
    }
    for (PinGroup& g : plan.motions) g.release = end;
    plan.release = end;
    return plan;
}

} // namespace pf
