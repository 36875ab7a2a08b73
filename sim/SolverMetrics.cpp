#include "SolverMetrics.h"

#include "Scenes.h"
#include "Simulation.h"

#include <cmath>

namespace pf {

namespace {

// Copies the integrator settings, keeping the scene's own switches (breaking, ...).
void applySettings(SimParams& p, const SimParams& s) {
    p.integrator = s.integrator;
    p.iterations = s.iterations;
    p.dt = s.dt;
    p.clampCompressed = s.clampCompressed;
    p.gravityOutsideFilter = s.gravityOutsideFilter;
    p.stiffness = s.stiffness;
    p.damping = s.damping;
    p.material = s.material;
    p.substeps = s.substeps;
    p.breaking = false;
}

} // namespace

World labWorld(const std::string& scene, int resolution, const SimParams& settings) {
    SceneOptions o;
    o.resolution = resolution;
    World w = *makeScene(scene, o);
    applySettings(w.params, settings);
    return w;
}

bool advanceFor(World& world, double seconds) {
    Simulation sim(std::move(world));
    const auto steps = static_cast<long>(std::lround(seconds / sim.world().params.dt));
    bool ok = true;
    for (long k = 0; k < steps && ok; ++k) ok = sim.step() == StepStatus::Ok;
    world = std::move(sim.world());
    return ok;
}

double trajectoryError(const Sheet& run, const Sheet& reference) {
    const auto& a = run.verts;
    const auto& b = reference.verts;
    if (a.size() != b.size()) return INFINITY;
    double sum = 0.0, mass = 0.0;
    Vec2 lo = b.X.front(), hi = lo;
    for (Index i = 0; i < b.size(); ++i) {
        sum += b.m[i] * (a.x[i] - b.x[i]).squaredNorm();
        mass += b.m[i];
        lo = lo.cwiseMin(b.X[i]);
        hi = hi.cwiseMax(b.X[i]);
    }
    return std::sqrt(sum / mass) / (hi - lo).norm();
}

double freeFallRatio(const SimParams& settings) {
    World w = labWorld("drape", 0, settings);
    w.script.pins.clear();
    for (auto& p : w.sheet.verts.pinned) p = 0;
    for (Vec3& x : w.sheet.verts.x) x = Vec3(x.x(), 0.5 - (x.z() + 0.1485), 0.0);
    w.groundEnabled = false;
    const double seconds = std::lround(0.1 / settings.dt) * settings.dt;
    if (!advanceFor(w, seconds)) return NAN;
    double m = 0, p = 0;
    for (Index i = 0; i < w.sheet.verts.size(); ++i) {
        m += w.sheet.verts.m[i];
        p += w.sheet.verts.m[i] * w.sheet.verts.v[i].y();
    }
    return -(p / m) / (settings.gravity * seconds);
}

double mechanicalEnergy(const World& world) {
    const Sheet& s = world.sheet;
    const auto& V = s.verts;
    double e = 0.0;
    for (Index i = 0; i < V.size(); ++i)
        e += V.m[i] * (0.5 * V.v[i].squaredNorm() + world.params.gravity * V.x[i].y());
    for (Index k = 0; k < s.springs.size(); ++k) {
        const double stretch =
            (V.x[s.springs.a[k]] - V.x[s.springs.b[k]]).norm() - s.springs.rest[k];
        e += 0.5 * world.params.stiffnessOf(s.springs.kind[k]) * stretch * stretch;
    }
    return e;
}

double energyRatio(const std::string& scene, int resolution, const SimParams& settings,
                   double seconds) {
    SimParams undamped = settings;
    undamped.damping.fill(0.0);
    World w = labWorld(scene, resolution, undamped);
    const double e0 = mechanicalEnergy(w);
    if (!advanceFor(w, seconds)) return NAN;
    return mechanicalEnergy(w) / e0;
}

} // namespace pf
