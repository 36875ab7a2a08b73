#pragma once

#include <string>

namespace pf {

// One cell of the solver lab's stability map: a scene run with one method at one
// step and stiffness scale (docs/solver-lab.md).
struct StabilityCase {
    std::string scene = "compress";
    std::string integrator = "jacobi";
    int sweeps = 1;
    bool clampCompressed = true;
    double dt = 1.0 / 240.0;
    double stiffnessScale = 1.0;
    double seconds = 1.0; // simulated time, capped at maxSteps steps
    int maxSteps = 2000;
    int resolution = 7;
};

enum class StabilityOutcome { Stable, Diverged, Overstrained, EnergyBlowup };

struct StabilityResult {
    StabilityOutcome outcome = StabilityOutcome::Stable;
    int steps = 0;            // steps run (up to the failure)
    double endStrain = 0.0;   // max |l/l0 - 1| at the end
    double peakKinetic = 0.0; // J
    double a = 0.0;           // h²k/m of a structural spring on the lightest free vertex
};

// A run fails on divergence (non-finite state or a position beyond 1 km), on
// kinetic energy beyond kMaxKineticEnergy, or on strain beyond 50 % at its end.
// Breaking is off: the map is about the integrators.
// 10 J is about 600 times the energy gravity can give these scenes (m g h ≈ 0.017 J for
// the 5 g sheet 35 cm up), i.e. a 5 g sheet at ~60 m/s: only an unstable step gets there.
inline constexpr double kMaxKineticEnergy = 10.0;
StabilityResult probeStability(const StabilityCase& c);

const char* outcomeName(StabilityOutcome o);

} // namespace pf
