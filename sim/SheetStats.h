#pragma once

#include "Sheet.h"

#include <cstdint>

namespace pf {

struct SheetStats {
    Index vertices = 0;
    Index springs = 0;
    Index triangles = 0;
    Index breaks = 0;     // active break events (creases that exist now)
    Index recoveries = 0; // break events that were recovered
    Index hinges = 0;     // hinge springs that exist now
    double totalMass = 0.0;
    double maxStrain = 0.0; // max |l/l0 - 1| over structural springs
    double rmsStrain = 0.0; // RMS of the same
    // Tension only, over the same springs (creases are no longer structural).
    double maxStretch = 0.0;     // max(l/l0 - 1, 0)
    double rmsStretch = 0.0;     // RMS of max(l/l0 - 1, 0)
    double maxCompression = 0.0; // max(1 - l/l0, 0)
};

SheetStats computeStats(const Sheet& sheet);

// FNV-1a over the bytes of every position and velocity, in storage order: two
// states hash equal only if they are bit-identical (up to hash collisions).
std::uint64_t stateHash(const Sheet& sheet);
// stateHash and the pins: what the editor compares to tell whether a sheet differs from
// its file (a pin changes nothing stateHash sees while the sheet rests).
std::uint64_t editedStateHash(const Sheet& sheet);

double totalMass(const Sheet& sheet);
Vec3 centreOfMass(const Sheet& sheet);

// Break events logged at `firstStep` or later and still in the sheet: how fast the sheet
// is breaking (the editor shows it per second, so a user sees damage settle). Only an
// undo or a redo recovers a break, and what it took back is not damage the user sees
// (the breaks of a stroke undone at once were counted for a second after the undo).
Index breaksSince(const Sheet& sheet, std::int64_t firstStep);

} // namespace pf
