#include "FoldWatch.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace pf {

namespace {

// Across the axis the flap must spread at least this far (rms) for its turn to be read.
constexpr double kReadableSpread = 0.002; // m
// A flap folded to an angle can close on past it only a little (it lies on the paper
// under it); readings are taken up to this far past it.
constexpr double kClosingRoom = 30.0; // degrees

} // namespace

void FoldWatch::start(const Sheet& sheet, std::vector<Index> flap, const Vec3& carried,
                      double angle, double time) {
    flap_ = std::move(flap);
    carried_ = carried.normalized();
    angle_ = angle;
    letGo_.clear();
    for (Index i : flap_) letGo_.push_back(sheet.verts.x[i]);
    due_ = time + kSeconds;
}

std::optional<double> FoldWatch::check(const Sheet& sheet, double time) {
    if (flap_.empty() || time < due_) return std::nullopt;
    const std::vector<Index> flap = std::exchange(flap_, {}); // read once
    Vec3 from = Vec3::Zero(), to = Vec3::Zero();
    for (std::size_t k = 0; k < flap.size(); ++k) {
        // Breaks only add vertices; what renumbers them (an undo) cancels the watch.
        if (flap[k] >= sheet.verts.size()) return std::nullopt;
        from += letGo_[k];
        to += sheet.verts.x[flap[k]];
    }
    from /= static_cast<double>(flap.size());
    to /= static_cast<double>(flap.size());
    // The turn about the carry's axis that best carries the offsets across it: the
    // least-squares angle, atan2(Σ n·(p × q), Σ p·q).
    const auto across = [&](const Vec3& d) { return Vec3(d - d.dot(carried_) * carried_); };
    double sine = 0.0, cosine = 0.0, spread = 0.0;
    for (std::size_t k = 0; k < flap.size(); ++k) {
        const Vec3 p = across(letGo_[k] - from), q = across(sheet.verts.x[flap[k]] - to);
        sine += carried_.dot(p.cross(q));
        cosine += p.dot(q);
        spread += p.squaredNorm();
    }
    if (spread < static_cast<double>(flap.size()) * kReadableSpread * kReadableSpread)
        return std::nullopt;
    double back = -std::atan2(sine, cosine) * 180.0 / std::numbers::pi;
    // A fold let go at `angle` can turn back at most that far (to flat), and close on
    // only a little: a turn near a half turn is read within those bounds.
    const double most = angle_ * 180.0 / std::numbers::pi + kClosingRoom;
    while (back > most) back -= 360.0;
    while (back <= most - 360.0) back += 360.0;
    return back;
}

} // namespace pf
