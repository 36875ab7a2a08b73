#pragma once

#include "Params.h"
#include "Sheet.h"

namespace pf {

// §3: for every interior structural edge without a hinge, if its two opposite
// vertices r and l have come closer than params.hingeThreshold times their rest
// distance |X_r - X_l|, insert an unbreakable hinge spring r-l whose rest length
// is the current distance (the fold is remembered) and log it. Returns the count.
int runHingePass(Sheet& sheet, const SimParams& params, std::int64_t step);

} // namespace pf
