#include "StabilityProbe.h"

#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"

#include <cmath>
#include <limits>

namespace pf {

namespace {

double kineticEnergy(const Vertices& V) {
    double e = 0.0;
    for (Index i = 0; i < V.size(); ++i) e += 0.5 * V.m[i] * V.v[i].squaredNorm();
    return e;
}

} // namespace

const char* outcomeName(StabilityOutcome o) {
    switch (o) {
    case StabilityOutcome::Stable:
        return "stable";
    case StabilityOutcome::Diverged:
        return "diverged";
    case StabilityOutcome::Overstrained:
        return "overstrained";
    case StabilityOutcome::EnergyBlowup:
        return "energy";
    }
    return "?";
}

StabilityResult probeStability(const StabilityCase& c) {
    SceneOptions options;
    options.resolution = c.resolution;
    World w = *makeScene(c.scene, options);
    w.params.integrator = c.integrator;
    w.params.iterations = c.sweeps;
    w.params.clampCompressed = c.clampCompressed;
    w.params.dt = c.dt;
    w.params.breaking = false;
    for (double& k : w.params.stiffness) k *= c.stiffnessScale;
    // xpbd takes its stretch stiffness from the material, E·t: the same stiffness as the
    // springs' here, so that a row of the map means one stiffness for every method
    // (bending keeps the material's D).
    w.params.material.stretchStiffness = w.params.stiffnessOf(SpringKind::Structural);

    StabilityResult r;
    double lightest = std::numeric_limits<double>::infinity();
    for (Index i = 0; i < w.sheet.verts.size(); ++i)
        if (!w.sheet.verts.pinned[i]) lightest = std::min(lightest, w.sheet.verts.m[i]);
    r.a = c.dt * c.dt * w.params.stiffnessOf(SpringKind::Structural) / lightest;

    Simulation sim(std::move(w));
    const int steps = std::min(c.maxSteps, static_cast<int>(std::lround(c.seconds / c.dt)));
    for (; r.steps < steps; ++r.steps) {
        if (sim.step() != StepStatus::Ok) {
            r.outcome = StabilityOutcome::Diverged;
            return r;
        }
        r.peakKinetic = std::max(r.peakKinetic, kineticEnergy(sim.world().sheet.verts));
        if (r.peakKinetic > kMaxKineticEnergy) {
            r.outcome = StabilityOutcome::EnergyBlowup;
            return r;
        }
    }
    r.endStrain = computeStats(sim.world().sheet).maxStrain;
    if (r.endStrain > 0.5) r.outcome = StabilityOutcome::Overstrained;
    return r;
}

} // namespace pf
