#include "FramePacer.h"

#include <algorithm>
#include <cmath>

namespace pf {

void FramePacer::restart() {
    owed_ = 0.0;
    windowWall_ = windowSimulated_ = 0.0;
    pace_ = 1.0;
    windowStepWall_ = 0.0;
    windowSteps_ = 0;
    stepSeconds_ = 0.0;
}

void FramePacer::stepped(int steps, double seconds) {
    windowSteps_ += std::max(0, steps);
    windowStepWall_ += std::max(0.0, seconds);
}

int FramePacer::stepsFor(double elapsed, double dt, double stepCost) {
    if (!(dt > 0.0) || !(elapsed > 0.0)) return 0;
    const int steps = stepsDue(elapsed, dt, stepCost);
    windowWall_ += elapsed;
    windowSimulated_ += steps * dt;
    if (windowWall_ >= 1.0) {
        pace_ = windowSimulated_ / windowWall_;
        windowWall_ = windowSimulated_ = 0.0;
        if (windowSteps_ > 0) stepSeconds_ = windowStepWall_ / windowSteps_;
        windowStepWall_ = 0.0;
        windowSteps_ = 0;
    }
    return steps;
}

int FramePacer::stepsDue(double elapsed, double dt, double stepCost) {
    const auto stepsIn = [dt](double seconds) { return std::max(1.0, std::round(seconds / dt)); };
    if (stepCost > dt) {
        owed_ = 0.0;
        return static_cast<int>(stepsIn(kFrameSeconds));
    }
    owed_ += elapsed;
    // A tick of exactly n steps' time is n steps, not n − 1 and a rounding error.
    const double due = std::floor(owed_ / dt + 1e-9);
    const double most = stepsIn(kCatchUpSeconds);
    if (due > most) {
        owed_ = 0.0;
        return static_cast<int>(most);
    }
    owed_ = std::max(0.0, owed_ - due * dt);
    return static_cast<int>(due);
}

} // namespace pf
