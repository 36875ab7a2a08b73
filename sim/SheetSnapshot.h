#pragma once

#include "Collisions.h"
#include "Simulation.h"

#include <vector>

namespace pf {

// An immutable picture of a World for drawing: geometry, topology and the overlay
// data. The simulation thread publishes these; the renderer only reads them.
struct SheetSnapshot {
    std::vector<Vec3> x;
    std::vector<Vec2> X; // material coordinates: where each vertex lies on the flat sheet
    std::vector<Triangle> tris;
    std::vector<std::array<Index, 2>> springEnds;
    std::vector<SpringKind> springKind;
    std::vector<std::uint8_t> breakable;
    std::vector<float> breakProbability;      // Eq. 10 per spring, as the last step drew it
    std::vector<float> strain;                // per spring: l/l0 - 1
    std::vector<std::uint8_t> recentlyBroken; // per spring: part of a break in the last second
    // Per spring: a half of a broken edge that has not broken itself, so that the crease
    // runs along it (through the vertex the break inserted, where the surface is).
    std::vector<std::uint8_t> creaseHalf;
    std::vector<float> vertexStrain; // per vertex: max |strain| of its structural springs
    std::vector<Index> pinned;       // the vertices that stand still (pins, a grab)
    std::vector<Index> held; // held for a while by a scripted hand that lets go (a fold's carry)
    SphereTool sphere;
    bool groundEnabled = true;
    double groundHeight = 0.0;
    double time = 0.0;
    std::int64_t step = 0;
    // Unique per makeSnapshot call: lets a renderer keep work done for this snapshot.
    std::uint64_t serial = 0;
};

// Whether the tool is drawn the same: where, how large, pressed or hovering.
bool toolDrawsTheSame(const SphereTool& a, const SphereTool& b);

// Whether a and b draw the same picture: everything but the clock (time, step, serial).
bool drawsTheSame(const SheetSnapshot& a, const SheetSnapshot& b);

// The vertices that stand still, split as a snapshot shows them: `pinned` by pins,
// `held` by a hand that lets go.
void pinnedAndHeld(const Simulation& sim, std::vector<Index>& pinned, std::vector<Index>& held);

// `recentSeconds`: how far back a break counts as recent. The break probabilities are
// the ones the simulation's last step drew (Simulation::breakProbabilities).
SheetSnapshot makeSnapshot(const Simulation& sim, double recentSeconds = 1.0);

} // namespace pf
