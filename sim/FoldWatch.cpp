#include "FoldWatch.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

namespace pf {

namespace {

// Across the axis the flap must spread at least this far (rms) for its turn to be read.
constexpr double kReadableSpread = 0.002; // m
// A flap folded to an angle can close on past it only a little (it lies on the paper
// under it); readings are taken up to this far past it.
constexpr double kClosingRoom = 30.0; // degrees
// Paper the carry left out is read up to this far round (see check).
constexpr double kLeftOutMost = 270.0; // degrees

// A turn in degrees, read into (top − 360°, top].
double within(double degrees, double top) {
    while (degrees > top) degrees -= 360.0;
    while (degrees <= top - 360.0) degrees += 360.0;
    return degrees;
}

// The turn about `axis` (degrees, right-handed) that best carries the offsets of `from`
// about their centroid to those of the same vertices now, across the axis: the
// least-squares angle, atan2(Σ n·(p × q), Σ p·q). Nothing if they spread too little
// across the axis to tell.
std::optional<double> turnAbout(const Vec3& axis, const std::vector<Index>& vertices,
                                const std::vector<Vec3>& from, const Sheet& sheet) {
    if (vertices.empty()) return std::nullopt;
    Vec3 was = Vec3::Zero(), now = Vec3::Zero();
    for (std::size_t k = 0; k < vertices.size(); ++k) {
        was += from[k];
        now += sheet.verts.x[vertices[k]];
    }
    was /= static_cast<double>(vertices.size());
    now /= static_cast<double>(vertices.size());
    const auto across = [&](const Vec3& d) { return Vec3(d - d.dot(axis) * axis); };
    double sine = 0.0, cosine = 0.0, spread = 0.0;
    for (std::size_t k = 0; k < vertices.size(); ++k) {
        const Vec3 p = across(from[k] - was), q = across(sheet.verts.x[vertices[k]] - now);
        sine += axis.dot(p.cross(q));
        cosine += p.dot(q);
        spread += p.squaredNorm();
    }
    if (spread < static_cast<double>(vertices.size()) * kReadableSpread * kReadableSpread)
        return std::nullopt;
    return std::atan2(sine, cosine) * 180.0 / std::numbers::pi;
}

} // namespace

void FoldWatch::start(const Sheet& sheet, std::vector<Index> flap, const Vec3& carried,
                      double angle, double time, LeftOut left) {
    flap_ = std::move(flap);
    left_ = std::move(left);
    carried_ = carried.normalized();
    angle_ = angle;
    letGo_.clear();
    for (Index i : flap_) letGo_.push_back(sheet.verts.x[i]);
    std::vector<std::uint8_t> watched(static_cast<std::size_t>(sheet.verts.size()), 0);
    for (const std::vector<Index>* group : {&flap_, &left_.vertices})
        for (Index i : *group)
            if (i >= 0 && i < sheet.verts.size()) watched[static_cast<std::size_t>(i)] = 1;
    rest_.clear();
    restLetGo_.clear();
    for (Index i = 0; i < sheet.verts.size(); ++i)
        if (!watched[static_cast<std::size_t>(i)]) {
            rest_.push_back(i);
            restLetGo_.push_back(sheet.verts.x[i]);
        }
    due_ = time + kSeconds;
    saidOpening_ = false;
}

std::optional<double> FoldWatch::turnedBack(const Sheet& sheet) const {
    for (const std::vector<Index>* group : {&flap_, &rest_})
        for (Index i : *group)
            if (i >= sheet.verts.size()) return std::nullopt;
    const auto turn = turnAbout(carried_, flap_, letGo_, sheet);
    if (!turn) return std::nullopt;
    const double restTurn = turnAbout(carried_, rest_, restLetGo_, sheet).value_or(0.0);
    // A fold let go at `angle` can turn back at most that far (to flat), and close on
    // only a little: a turn near a half turn is read within those bounds.
    return within(restTurn - *turn, angle_ * 180.0 / std::numbers::pi + kClosingRoom);
}

bool FoldWatch::openingEarly(const Sheet& sheet, double time, double past) {
    if (flap_.empty() || saidOpening_ || time >= due_) return false;
    const auto back = turnedBack(sheet);
    if (!back || *back <= past) return false;
    saidOpening_ = true;
    return true;
}

std::optional<FoldWatch::Reading> FoldWatch::check(const Sheet& sheet, double time) {
    if (flap_.empty() || time < due_) return std::nullopt;
    // Vertices are renumbered only by what cancels the watch (an undo); checked all the
    // same, before any reading, so that a sheet that lost them says nothing at all.
    for (const std::vector<Index>* group : {&flap_, &rest_, &left_.vertices})
        for (Index i : *group)
            if (i >= sheet.verts.size()) {
                cancel();
                return std::nullopt;
            }
    const double folded = angle_ * 180.0 / std::numbers::pi;
    Reading reading;
    reading.turnedBack = turnedBack(sheet);
    const std::vector<Index> flap = std::exchange(flap_, {}); // read once
    rest_.clear();
    const LeftOut left = std::exchange(left_, {});
    // What the carry left out is read vertex by vertex (of a stack, one layer may go
    // round and the next stay), each by its turn about the line since the fold began.
    // The carry took the flap round by a half turn before it opened it back to the
    // fold's angle, so paper that followed it may lie anywhere up to a half turn, and past
    // it by as much as it started under the line's plane (a lower layer, 30-45° under
    // from the line, ends 210-225° on); it lies unfolded if it turned less than half the
    // fold's angle. Turned back against the carry by more than a quarter turn is not
    // what paper left out does.
    const auto across = [&](const Vec3& x) {
        const Vec3 d = x - left.pivot;
        return Vec3(d - d.dot(carried_) * carried_);
    };
    std::size_t unfolded = 0;
    for (std::size_t k = 0; k < left.vertices.size(); ++k) {
        const Vec3 p = across(left.atStart[k]), q = across(sheet.verts.x[left.vertices[k]]);
        const double turn =
            std::atan2(carried_.dot(p.cross(q)), p.dot(q)) * 180.0 / std::numbers::pi;
        if (within(turn, kLeftOutMost) < 0.5 * folded) ++unfolded;
    }
    if (unfolded > 0)
        reading.unfoldedShare =
            static_cast<double>(unfolded) / static_cast<double>(left.vertices.size() + flap.size());
    if (!reading.turnedBack && reading.unfoldedShare == 0.0) return std::nullopt;
    return reading;
}

} // namespace pf
