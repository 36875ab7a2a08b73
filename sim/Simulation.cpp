#include "Simulation.h"

#include "CreaseRelaxation.h"

#include <algorithm>
#include <atomic>
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

// `before`: the positions the step began from (the stretch test asks what the step did).
bool stateIsSane(const Sheet& sheet, const std::vector<Vec3>& before, bool boundedStretch,
                 WorkerPool& pool) {
    const Vertices& V = sheet.verts;
    const double limit2 = kDivergenceRadius * kDivergenceRadius;
    std::atomic<bool> insane{false};
    pool.forRanges(V.size(), [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i)
            if (!(V.x[i].squaredNorm() < limit2) || !V.v[i].allFinite()) {
                insane = true;
                return;
            }
    });
    if (insane || !boundedStretch) return !insane;
    const Springs& S = sheet.springs;
    const double stretch2 = kDivergenceStretch * kDivergenceStretch;
    pool.forRanges(S.size(), [&](Index begin, Index end) {
        for (Index s = begin; s < end; ++s) {
            if (S.kind[s] != SpringKind::Structural) continue;
            const double length2 = (V.x[S.a[s]] - V.x[S.b[s]]).squaredNorm();
            if (length2 > stretch2 * S.rest[s] * S.rest[s] &&
                std::sqrt(length2) > S.rest[s] + kDivergenceStretchReach &&
                length2 > kDivergenceGrowth * kDivergenceGrowth *
                              (before[S.a[s]] - before[S.b[s]]).squaredNorm()) {
                insane = true;
                return;
            }
        }
    });
    return !insane;
}

// to = from, on the pool's threads.
void copyOnto(std::vector<Vec3>& to, const std::vector<Vec3>& from, WorkerPool& pool) {
    to.resize(from.size());
    pool.forRanges(static_cast<Index>(from.size()), [&](Index begin, Index end) {
        std::copy(from.begin() + begin, from.begin() + end, to.begin() + begin);
    });
}

// Half a millimetre: a few sheets of paper, and within the tool's grip (kToolReach).
constexpr double kToolAboveDesk = 0.0005;

// The tool is rigid and so is the desk: however deep a script or the mouse asks it to
// go, the sphere rests on the desk, with the paper between them, instead of pressing
// the paper through the desk or squeezing it flat to nothing.
//
// Where it was a step before is held above the desk the same way. A tool that starts
// touching from a place into the desk (a hovering tool touches nothing and goes where it
// is asked) was lifted out of it in one step, and that lift was taken as its velocity:
// pressed from a hover 1.8 cm into the desk, 4.4 m/s upward, whose grip flung the sheet
// at 3.5 m/s and broke 158 springs in the first frame. (The editor hovers one radius
// above the paper or desk under the cursor, 0.5 mm too low over the bare desk.)
void keepToolAboveDesk(World& w) {
    SphereTool& sp = w.sphere;
    if (!w.groundEnabled || !sp.active) return;
    const double lowest = w.groundHeight + sp.radius + kToolAboveDesk;
    if (!(sp.center.y() < lowest)) return;
    Vec3 previous = sp.center - sp.velocity * w.params.dt;
    previous.y() = std::max(previous.y(), lowest);
    sp.center.y() = lowest;
    sp.velocity = (sp.center - previous) / w.params.dt;
}

void keepOutOfContacts(World& w, const std::vector<Index>& vertices) {
    auto& V = w.sheet.verts;
    const SphereTool& sp = w.sphere;
    for (Index i : vertices) {
        if (sp.active) {
            const Vec3 d = V.x[i] - sp.center;
            const double dist = d.norm();
            if (dist < sp.radius && dist > 0.0) V.x[i] = sp.center + d * (sp.radius / dist);
        }
        if (w.groundEnabled && V.x[i].y() < w.groundHeight) V.x[i].y() = w.groundHeight;
    }
}

} // namespace

StepStatus Simulation::step() {
    World& w = world_;
    SimParams& p = w.params;
    if (p.integrator != integratorName_) {
        if (setIntegrator(p.integrator))
            w.sheet.paper.meshChanged(); // another integrator moved the sheet meanwhile
        else
            p.integrator = integratorName_;
    }
    Sheet& sheet = w.sheet;
    lastBreaks_ = lastHinges_ = 0;

    if (scriptHeld_)
        holdScriptStill(w.script, sheet, w.sphere, heldVertex_);
    else
        applyScript(w.script, w.time, p.dt, sheet, w.sphere, heldVertex_);
    // The paper's springs are soft enough to be squeezed under a sphere that dips below
    // the desk (the press scene is drawn for them); real paper is not.
    if (integrator_->resolvesContacts()) keepToolAboveDesk(w);

    // A sheet too small for every loop of the step to be shared runs on one thread: a
    // loop shared while the next is not moves its data between the cores' caches, which
    // measured slower than one thread (0.8 times at 1,000-3,000 vertices).
    WorkerPool& pool =
        sheet.verts.size() >= 2 * WorkerPool::kMinPerPart ? *pool_ : WorkerPool::serial();
    // A sheet that slept through the last step is integrated in this one only if something
    // wakes it, and then by xpbd, the one integrator that sleeps, which does not read the
    // stars: comparing the mesh with theirs took 41 % of the editor's simulation thread
    // over a resting 14,100-vertex sheet. They are brought up to date below if it woke
    // (the break pass reads them); the integrator is lent none meanwhile.
    const bool slept = integrator_->asleep();
    if (!slept) stars_->refresh(sheet, pool);
    const StepWorkers workers{&pool, stars_.get()};
    // Lent at every step: a Simulation moved into place since holds its stars elsewhere.
    integrator_->lendWorkers({&pool, slept ? nullptr : stars_.get()});
    copyOnto(savedX_, sheet.verts.x, pool);
    copyOnto(savedV_, sheet.verts.v, pool);
    savedPaper_ = sheet.paper;
    if (integrator_->resolvesContacts()) {
        integrator_->setContacts({w.sphere, w.groundEnabled, w.groundHeight, heldVertex_});
        integrator_->advance(sheet, p);
    } else {
        integrator_->advance(sheet, p);
        // Contact friction is expressed per reference step so it does not depend on h.
        const double ref = p.breakReferenceStep;
        collideSphere(sheet, w.sphere, std::pow(1.0 - p.sphereFriction, p.dt / ref), pool);
        if (w.groundEnabled)
            collideGround(sheet, w.groundHeight, std::pow(1.0 - p.groundFriction, p.dt / ref),
                          pool);
    }

    // A sheet that slept through the step did not move: its springs are as they were.
    if (!stateIsSane(sheet, savedX_, integrator_->boundsStretch() && !slept, pool)) {
        sheet.verts.x = savedX_;
        sheet.verts.v = savedV_;
        sheet.paper = savedPaper_;
        setIntegrator(integratorName_); // a fresh one: nothing of the failed step stays
        sheetEdited();
        return StepStatus::Diverged;
    }

    // Paper drawn taut stopped the tool short of where it was asked to go: it stays
    // there, and the next step's move sets off from there.
    if (const auto held = integrator_->toolHeldAt()) {
        const Vec3 start = w.sphere.center - w.sphere.velocity * p.dt;
        w.sphere.center = *held;
        w.sphere.velocity = (*held - start) / p.dt;
    }

    // A sheet at rest is not being loaded, so it does not break: Eq. 10 would otherwise
    // keep drawing on edges left compressed where the sheet came to rest.
    if (damageAllowed_ && !integrator_->asleep()) {
        if (slept) stars_->refresh(sheet, pool);
        const Index before = sheet.verts.size();
        if (p.breaking)
            lastBreaks_ = runBreakPass(sheet, p, w.rng, w.stepCount, breakScratch_, workers);
        // Without breaking the next breakProbabilities gives zeros, at the cost of a fill.
        probabilitiesCurrent_ = p.breaking;
        // Eq. 11 lifts a new vertex off the edge toward the side it bends to, which
        // can be into the desk or the tool; an integrator that keeps the sheet out of
        // them gets the vertex back on their surface.
        if (keepsEdgeLengths(p.integrator) && sheet.verts.size() > before) {
            const std::vector<Index> moved = relaxAroundNewVertices(sheet, before);
            if (integrator_->resolvesContacts()) keepOutOfContacts(w, moved);
        } else if (integrator_->resolvesContacts() && sheet.verts.size() > before) {
            std::vector<Index> added;
            for (Index i = before; i < sheet.verts.size(); ++i) added.push_back(i);
            keepOutOfContacts(w, added);
        }
        // The breaks may have changed the mesh since the stars were refreshed: not lent.
        if (p.hinges)
            lastHinges_ = runHingePass(sheet, p, w.stepCount, hingeScratch_, {&pool, nullptr});
        // Springs the two passes added are drawn for from the next step on.
        if (probabilitiesCurrent_)
            breakScratch_.probability.resize(static_cast<std::size_t>(sheet.springs.size()), 0.0f);
    }

    ++w.stepCount;
    w.time += p.dt;
    return StepStatus::Ok;
}

const std::vector<float>& Simulation::breakProbabilities() const {
    if (!probabilitiesCurrent_ ||
        breakScratch_.probability.size() != static_cast<std::size_t>(world_.sheet.springs.size())) {
        if (damageAllowed_)
            computeBreakProbabilities(world_.sheet, world_.params, breakScratch_);
        else
            breakScratch_.probability.assign(world_.sheet.springs.size(), 0.0f);
        probabilitiesCurrent_ = true;
    }
    return breakScratch_.probability;
}

} // namespace pf
