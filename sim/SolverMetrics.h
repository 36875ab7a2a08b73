#pragma once

#include "Params.h"
#include "World.h"

#include <string>

namespace pf {

// The solver lab's measurements (docs/solver-lab.md). Every lab run has breaking
// off: the lab compares integrators, and a break would change the topology.

// A scene set up for the lab at a resolution with the given integrator settings.
World labWorld(const std::string& scene, int resolution, const SimParams& settings);

// Steps a World for `seconds` of simulated time; false if it diverged.
bool advanceFor(World& world, double seconds);

// Mass-weighted RMS distance between two runs of the same sheet (same vertices),
// divided by the sheet's material diagonal.
double trajectoryError(const Sheet& run, const Sheet& reference);

// Centre-of-mass acceleration over 0.1 s divided by g for a sheet hanging straight
// down (springs along gravity), released from rest, no ground. Exact backward Euler
// gives 1; the paper's step loses most of it (docs/solver-lab.md).
double freeFallRatio(const SimParams& settings);

// Total mechanical energy: kinetic, spring (½ k (l - L)² per spring) and gravitational
// (m g y, the ground at y = 0), in joules.
double mechanicalEnergy(const World& world);

// E(t)/E(0) after `seconds` of `scene` with damping off (exact integration keeps 1;
// implicit steps lose energy, unstable ones gain it). NaN if the run diverged.
double energyRatio(const std::string& scene, int resolution, const SimParams& settings,
                   double seconds);

} // namespace pf
