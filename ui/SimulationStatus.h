#pragma once

#include <cstdint>

namespace pf {

// Live statistics of the running simulation, for the status bar and the tests.
struct SimulationStatus {
    std::int64_t step = 0;
    // Wall time of one step: while playing, the mean over the pace's last second (FramePacer);
    // paused, the last step's own; 0 on a sheet that has taken no step.
    double stepSeconds = 0.0;
    int vertices = 0, springs = 0, breaks = 0, hinges = 0;
    int breaksLastSecond = 0; // breaks made in the last second of simulated time
    // max(l/l0 - 1, 0) over the uncreased structural springs: how far the paper is pulled
    // longer (SheetStats). Not |l/l0 - 1|: across a fold most of that is the chord of
    // paper bending between two vertices, and a user read 16-22 % there as stretch.
    double maxStretch = 0.0, rmsStretch = 0.0;
    int threads = 1;   // the step runs on
    double pace = 1.0; // simulated seconds per wall-clock second while playing (FramePacer)
    bool playing = false;
    bool folding = false;      // a fold is under way: undo, redo and the other tools wait
    bool settling = false;     // a Settle is under way (not frozen yet): undo and redo wait
    bool settled = false;      // a Settle froze the sheet: it stays as it is until an edit
    bool asleep = false;       // the integrator sleeps: nothing moves, a step costs almost nothing
    double grabHeldBack = 0.0; // EditSession::grabHeldBack (m)
    std::uint64_t sheetHash = 0; // editedStateHash: tells whether it differs from a file
    // Held pressed flat, a fold's sheet may sleep; it is being folded, not lying at rest.
    bool resting() const { return asleep && !folding; }
};

} // namespace pf
