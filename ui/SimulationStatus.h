#pragma once

#include <cstdint>

namespace pf {

// Live statistics of the running simulation, for the status bar and the tests.
struct SimulationStatus {
    std::int64_t step = 0;
    double stepSeconds = 0.0; // wall time of one step, averaged over the last frame
    int vertices = 0, springs = 0, breaks = 0, hinges = 0;
    int breaksLastSecond = 0;                // breaks made in the last second of simulated time
    double maxStrain = 0.0, rmsStrain = 0.0; // |l/l0 - 1| over structural springs
    int threads = 1;                         // the step runs on
    bool playing = false;
    bool folding = false;        // a fold is under way: undo, redo and the other tools wait
    std::uint64_t sheetHash = 0; // editedStateHash: tells whether it differs from a file
};

} // namespace pf
