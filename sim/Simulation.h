#pragma once

#include "Breaking.h"
#include "Hinges.h"
#include "Integrator.h"
#include "World.h"

#include <memory>
#include <string>

namespace pf {

enum class StepStatus {
    Ok,
    // The integrator produced a non-finite or exploding state; positions and
    // velocities were put back as they were before the step.
    Diverged,
};

// Steps a World. One step, top to bottom:
//   1. the scene script sets the sphere and the pinned vertices' velocities
//   2. the integrator updates velocities and positions (Eq. 3-6)
//   3. sphere and ground collisions
//   4. divergence check (rolls back x and v on failure)
//   5. stochastic breaking (Eq. 10-11)
//   6. hinge insertion (§3)
//   7. the clock advances
class Simulation {
  public:
    explicit Simulation(World world);

    // Fails (returns false and keeps the old integrator) for an unknown name.
    bool setIntegrator(const std::string& name);

    StepStatus step();

    // Threads the step runs on (default: all the machine's; 0 or less means those). The
    // result is the same, bit for bit, on any number (test_determinism).
    void setThreads(int threads) { pool_->setThreads(threads); }
    int threads() const { return pool_->threads(); }

    // The sheet's state was set from outside (an undo giving back what the user saw): the
    // integrator starts afresh from it, as after loading a file.
    void restartIntegrator() {
        setIntegrator(world_.params.integrator);
        sheetEdited();
    }

    // Eq. 10 per spring (zero where a spring cannot break, and for one that broke), as the
    // last step's break pass drew it; worked out afresh, once, after the sheet or φ
    // changed outside a step. All zero while damage is not allowed.
    const std::vector<float>& breakProbabilities() const;
    // The sheet or its parameters were changed between steps (undo, redo, new φ).
    void sheetEdited() { probabilitiesCurrent_ = false; }
    // Held, the scene's scripted motions stand still: its pinned vertices and its sphere
    // stay where they are (a Settle keeps the sheet as the user saw it).
    void holdScript(bool held) { scriptHeld_ = held; }
    // Off: steps neither break nor hinge, whatever the parameters say (a settle).
    void allowDamage(bool allowed) {
        damageAllowed_ = allowed;
        sheetEdited();
    }

    // A vertex the user holds (a grab): the scene script leaves it to the user.
    void setHeldVertex(Index vertex) { heldVertex_ = vertex; }
    Index heldVertex() const { return heldVertex_; }

    World& world() { return world_; }
    const World& world() const { return world_; }

    int lastBreaks() const { return lastBreaks_; }
    int lastHinges() const { return lastHinges_; }
    // True while the integrator lets a sheet at rest sleep (costs almost nothing).
    bool asleep() const { return integrator_->asleep(); }
    // The integrator stepping the sheet, to read what it measures (a step that fails makes
    // a new one, whose counts start again).
    const Integrator& integrator() const { return *integrator_; }

  private:
    World world_;
    std::unique_ptr<Integrator> integrator_;
    std::string integratorName_;
    std::unique_ptr<WorkerPool> pool_ = std::make_unique<WorkerPool>(0);
    // Current for the sheet from the start of each step's integration, except in a step
    // after one the sheet slept through (then from its break pass on). On the heap, like
    // the pool, so that what the integrator was lent stays put when a Simulation moves.
    std::unique_ptr<VertexStars> stars_ = std::make_unique<VertexStars>();
    HingeScratch hingeScratch_;
    // Mutable: breakProbabilities() fills it in when an edit left it behind the sheet.
    mutable BreakScratch breakScratch_;
    std::vector<Vec3> savedX_, savedV_;
    PaperState savedPaper_;
    int lastBreaks_ = 0;
    int lastHinges_ = 0;
    mutable bool probabilitiesCurrent_ = false;
    bool damageAllowed_ = true;
    bool scriptHeld_ = false;
    Index heldVertex_ = kNone;
};

} // namespace pf
