#pragma once

#include "Params.h"
#include "Sheet.h"
#include "StepWorkers.h"

#include <vector>

namespace pf {

// §3: for every interior structural edge without a hinge, if its two opposite
// vertices r and l have come closer than params.hingeThreshold times their rest
// distance |X_r - X_l|, insert an unbreakable hinge spring r-l whose rest length
// is the current distance (the fold is remembered) and log it. Returns the count.
// With workers, the edges are tested on their threads and the hinges inserted in index
// order on the caller's: the same hinges on any number of threads.
struct HingeScratch {
    struct Found {
        Index spring;
        double rest;
    };
    std::vector<std::vector<Found>> found; // per chunk of the springs, in order
};
int runHingePass(Sheet& sheet, const SimParams& params, std::int64_t step);
int runHingePass(Sheet& sheet, const SimParams& params, std::int64_t step, HingeScratch& scratch,
                 const StepWorkers& workers);

// Whether structural edge `spring` can take a hinge: it has two faces and none yet.
bool canHinge(const Sheet& sheet, Index spring);

// Inserts the hinge across `spring` (canHinge must hold) with rest length `rest`, logs
// it as a damage event at `step` and returns the event's id.
Index insertHinge(Sheet& sheet, Index spring, double rest, std::int64_t step);

} // namespace pf
