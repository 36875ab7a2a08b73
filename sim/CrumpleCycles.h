#pragma once

#include "World.h"

#include <functional>
#include <string>
#include <vector>

namespace pf {

// The crease network after one cycle of the crumple-cycles scene (Scenes.h).
struct CrumpleCycle {
    int cycle = 0;             // 1-based
    Index vertices = 0;        // at the cycle's end
    Index breaks = 0;          // active break events
    double creaseLength = 0.0; // m, CreaseNetwork::totalLength
};

// L(n) = a + b ln n by least squares over n = 1..N, and its coefficient of
// determination. Repeatedly crumpled and flattened paper grows its total crease length
// about so (Gottesman et al. 2018; Andrejevic et al. 2021).
struct LogarithmicFit {
    double a = 0.0, b = 0.0, r2 = 0.0;
};
LogarithmicFit fitLogarithmic(const std::vector<double>& values);

struct CrumpleReport {
    std::vector<CrumpleCycle> cycles;
    LogarithmicFit fit;           // of creaseLength over the cycles
    std::vector<double> segments; // m, crease runs after the last cycle (CreaseNetwork)
    std::string error;            // set when a step diverged; cycles holds those before
};

// Runs `world` (a crumple-cycles scene) through `cycles` of its cycles and measures the
// creases at the end of each. `progress` is shown each cycle, and the sheet, as it ends.
CrumpleReport
runCrumpleCycles(World world, int cycles,
                 const std::function<void(const CrumpleCycle&, const Sheet&)>& progress = {});

} // namespace pf
