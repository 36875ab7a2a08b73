#include "Simulation.h"

#include "Hinges.h"

#include <cmath>
#include <stdexcept>

namespace pf {

Simulation::Simulation(World world) : world_(std::move(world)) {
    if (!setIntegrator(world_.params.integrator))
        throw std::invalid_argument("unknown integrator: " + world_.params.integrator);
    world_.sheet.reserveFor(world_.sheet.verts.size());
}

bool Simulation::setIntegrator(const std::string& name) {
    auto made = makeIntegrator(name);
    if (!made) return false;
    integrator_ = std::move(made);
    integratorName_ = name;
    world_.params.integrator = name;
    return true;
}

namespace {

bool stateIsSane(const Vertices& V) {
    const double limit2 = kDivergenceRadius * kDivergenceRadius;
    for (Index i = 0; i < V.size(); ++i)
        if (!(V.x[i].squaredNorm() < limit2) || !V.v[i].allFinite()) return false;
    return true;
}

} // namespace

StepStatus Simulation::step() {
    World& w = world_;
    SimParams& p = w.params;
    if (p.integrator != integratorName_ && !setIntegrator(p.integrator))
        p.integrator = integratorName_;
    Sheet& sheet = w.sheet;
    lastBreaks_ = lastHinges_ = 0;

    applyScript(w.script, w.time, p.dt, sheet, w.sphere);

    savedX_ = sheet.verts.x;
    savedV_ = sheet.verts.v;
    if (integrator_->resolvesContacts()) {
        integrator_->setContacts({w.sphere, w.groundEnabled, w.groundHeight});
        integrator_->advance(sheet, p);
    } else {
        integrator_->advance(sheet, p);
        // Contact friction is expressed per reference step so it does not depend on h.
        const double ref = p.breakReferenceStep;
        collideSphere(sheet, w.sphere, std::pow(1.0 - p.sphereFriction, p.dt / ref));
        if (w.groundEnabled)
            collideGround(sheet, w.groundHeight, std::pow(1.0 - p.groundFriction, p.dt / ref));
    }

    if (!stateIsSane(sheet.verts)) {
        sheet.verts.x = savedX_;
        sheet.verts.v = savedV_;
        return StepStatus::Diverged;
    }

    if (p.breaking) lastBreaks_ = runBreakPass(sheet, p, w.rng, w.stepCount, breakScratch_);
    if (p.hinges) lastHinges_ = runHingePass(sheet, p, w.stepCount);

    ++w.stepCount;
    w.time += p.dt;
    return StepStatus::Ok;
}

} // namespace pf
