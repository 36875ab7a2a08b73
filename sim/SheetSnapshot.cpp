#include "SheetSnapshot.h"

#include <atomic>
#include <cmath>

namespace pf {

bool toolDrawsTheSame(const SphereTool& a, const SphereTool& b) {
    return a.center == b.center && a.radius == b.radius && a.active == b.active &&
           a.hovering == b.hovering;
}

bool drawsTheSame(const SheetSnapshot& a, const SheetSnapshot& b) {
    return a.x == b.x && a.X == b.X && a.tris == b.tris && a.springEnds == b.springEnds &&
           a.springKind == b.springKind && a.breakable == b.breakable &&
           a.breakProbability == b.breakProbability && a.strain == b.strain &&
           a.recentlyBroken == b.recentlyBroken && a.creaseHalf == b.creaseHalf &&
           a.vertexStrain == b.vertexStrain && a.pinned == b.pinned && a.held == b.held &&
           toolDrawsTheSame(a.sphere, b.sphere) && a.groundEnabled == b.groundEnabled &&
           a.groundHeight == b.groundHeight;
}

void pinnedAndHeld(const Simulation& sim, std::vector<Index>& pinned, std::vector<Index>& held) {
    const World& world = sim.world();
    const Sheet& s = world.sheet;
    pinned.clear();
    held.clear();
    // A hand that lets go (the Fold tool's carry, the Grab tool's grip) is not a pin: its
    // vertices are marked apart (a user could not tell a carried flap's crosses, or the
    // grabbed vertex's, from the pins they had set).
    std::vector<std::uint8_t> byHand(static_cast<std::size_t>(s.verts.size()), 0);
    for (const PinGroup& g : world.script.pins)
        if (std::isfinite(g.release) && world.time < g.release)
            for (Index i : g.vertices)
                if (i >= 0 && i < s.verts.size()) byHand[i] = 1;
    if (const Index h = sim.heldVertex(); h >= 0 && h < s.verts.size()) byHand[h] = 1;
    for (Index i = 0; i < s.verts.size(); ++i)
        if (s.verts.pinned[i]) (byHand[i] ? held : pinned).push_back(i);
}

SheetSnapshot makeSnapshot(const Simulation& sim, double recentSeconds) {
    const World& world = sim.world();
    const Sheet& s = world.sheet;
    const auto& S = s.springs;
    const auto& x = s.verts.x;
    SheetSnapshot snap;
    snap.x = x;
    snap.X = s.verts.X;
    snap.tris = s.tris;
    snap.springKind = S.kind;
    snap.breakable = S.breakable;
    snap.springEnds.resize(static_cast<std::size_t>(S.size()));
    snap.breakProbability = sim.breakProbabilities();
    snap.strain.resize(static_cast<std::size_t>(S.size()));
    snap.recentlyBroken.assign(static_cast<std::size_t>(S.size()), 0);
    snap.vertexStrain.assign(x.size(), 0.0f);
    pinnedAndHeld(sim, snap.pinned, snap.held);
    for (Index k = 0; k < S.size(); ++k) {
        const Index a = S.a[k], b = S.b[k];
        snap.springEnds[k] = {a, b};
        const double l = (x[a] - x[b]).norm();
        snap.strain[k] = static_cast<float>(l / S.rest[k] - 1.0);
        if (S.kind[k] == SpringKind::Structural) {
            const float e = std::abs(snap.strain[k]);
            snap.vertexStrain[a] = std::max(snap.vertexStrain[a], e);
            snap.vertexStrain[b] = std::max(snap.vertexStrain[b], e);
        }
    }
    // Read from the creases (each names its break), not from the whole log of events,
    // which undo and redo lengthen.
    snap.creaseHalf.assign(static_cast<std::size_t>(S.size()), 0);
    const auto events = static_cast<Index>(s.events.size());
    for (Index k = 0; k < S.size(); ++k) {
        if (S.kind[k] != SpringKind::Crease || S.event[k] < 0 || S.event[k] >= events) continue;
        const DamageEvent& ev = s.events[S.event[k]];
        for (const Index half : {ev.springs[0], ev.springs[1]})
            if (half >= 0 && half < S.size() && S.kind[half] == SpringKind::Structural)
                snap.creaseHalf[half] = 1;
    }
    const auto recentSteps = static_cast<std::int64_t>(std::ceil(recentSeconds / world.params.dt));
    // The log is in step order (a redo logs again at its own step), so only its tail
    // can be recent.
    for (auto it = s.events.rbegin(); it != s.events.rend(); ++it) {
        const DamageEvent& ev = *it;
        if (world.stepCount - ev.step > recentSteps) break;
        if (!ev.active || ev.kind != EventKind::Break) continue;
        snap.recentlyBroken[ev.edge] = 1;
        snap.recentlyBroken[ev.springs[0]] = 1;
        snap.recentlyBroken[ev.springs[1]] = 1;
    }
    snap.sphere = world.sphere;
    snap.groundEnabled = world.groundEnabled;
    snap.groundHeight = world.groundHeight;
    snap.time = world.time;
    snap.step = world.stepCount;
    static std::atomic<std::uint64_t> serials{0};
    snap.serial = ++serials;
    return snap;
}

} // namespace pf
