#pragma once

#include "Sheet.h"
#include "Simulation.h"
#include "World.h"

namespace pf::test {

// Two triangles (i, r, j) and (i, j, l) sharing edge i-j, ids i=0, j=1, r=2, l=3,
// with 5 structural springs (edge i-j is spring 0) and the bending spring r-l.
// Material coordinates: i=(-0.5, 0), j=(0.5, 0), r=(0, 0.5), l=(0, -0.5), so l0 = 1.
// Positions: i=(-0.4, 0, 0), j=(0.4, 0, 0), r=(0, 0.3, 0.4), l=(0, 0.3, -0.4):
// the edge is compressed to l = 0.8 and folded into a valley with face normals
// (0, 0.8, -0.6) and (0, 0.8, 0.6), so n_i = n_j = (0, 1, 0).
Sheet makeFoldedQuad();

// A flat sheet with rows × columns vertices whose positions are jittered
// out of plane and in plane (deterministically from seed), so that every
// interior edge is a valid break candidate with two faces.
Sheet makeJitteredSheet(int columns, int rows, unsigned seed);

// Pins the last row of an A4 sheet built at `resolution` (the edge farthest from the
// press scene's start) in place for the whole run.
void holdFarEdge(World& w, int resolution);

// Steps until the sheet sleeps, at most `maxSteps`; returns the steps taken, -1 if the
// sheet never slept, or kStepFailed if a step did not return StepStatus::Ok.
inline constexpr int kStepFailed = -2;
int stepUntilAsleep(Simulation& sim, int maxSteps = 2400);

} // namespace pf::test
