#pragma once

#include "Collisions.h"
#include "Params.h"
#include "Rng.h"
#include "SceneScript.h"
#include "Sheet.h"

#include <cstdint>
#include <string>

namespace pf {

// Everything a run consists of: the sheet, its parameters, the tool, the script,
// the random generator and the clock. Copying a World copies the whole run.
struct World {
    std::string scene;
    Sheet sheet;
    SimParams params;
    SphereTool sphere;
    SceneScript script;
    bool groundEnabled = true;
    double groundHeight = 0.0;
    Rng rng;
    std::uint64_t seed = 1;
    double time = 0.0;
    std::int64_t stepCount = 0;
};

} // namespace pf
