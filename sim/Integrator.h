#pragma once

#include "Collisions.h"
#include "Params.h"
#include "Sheet.h"
#include "StepWorkers.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pf {

// Advances velocities and positions of a sheet by one step of length params.dt.
// Pinned vertices keep the velocity the scene script gave them and move with it.
// An integrator owns its scratch memory, so a step allocates nothing once warm.
// What an integrator that resolves contacts inside its step needs to know of them.
struct ContactScene {
    SphereTool sphere; // center and velocity at the end of the step
    bool ground = false;
    double groundHeight = 0.0;
    // The pinned vertex a hand holds (a grab), or kNone: its velocity at the start of
    // the step is the hand's. An integrator may hold it by a grip rather than rigidly.
    Index hand = kNone;
};

class Integrator {
  public:
    virtual ~Integrator() = default;
    virtual void advance(Sheet& sheet, const SimParams& params) = 0;
    // True if advance() resolves the sphere and the ground itself (then the simulation
    // does not collide again after it); setContacts() is called before each advance().
    virtual bool resolvesContacts() const { return false; }
    virtual void setContacts(const ContactScene&) {}
    // The simulation's threads and stars (refreshed before each advance(); none after a
    // step the sheet slept through, which only xpbd, which reads no stars, does). An
    // integrator that can use them keeps them; it works on one thread without.
    virtual void lendWorkers(const StepWorkers&) {}
    // True while the sheet sleeps: at rest, untouched, and not integrated.
    virtual bool asleep() const { return false; }
    // Where the last step held the tool back, short of where it was asked to go: paper
    // drawn taut (by pins, say) that it could not push further without stretching.
    virtual std::optional<Vec3> toolHeldAt() const { return std::nullopt; }
    // True if a structural spring stretched kDivergenceStretch times means the step blew
    // up. The paper's Jacobi (any sweeps, 3×3 or scalar blocks) is a truncated iteration
    // whose stretch has no such bound (11,350 % in `drop` at resolution 60, 1,383 % in
    // `compress` at 90, and it goes on without blowing up): for it only positions beyond
    // kDivergenceRadius count.
    virtual bool boundsStretch() const { return true; }
};

// Names: "jacobi" (Eq. 6, 3×3 blocks), "jacobi-scalar" (Eq. 6, k·I blocks),
// "symplectic" (symplectic Euler), "backward-euler" (Eq. 3 solved by conjugate gradient),
// "xpbd" (implicit plate bending + sub-stepped XPBD, from the material's constants).
// Returns nullptr for an unknown name.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);
const std::vector<std::string>& integratorNames();

// Whether the integrator holds the paper at its real stretch stiffness ("xpbd"): its
// edges keep their length, so a break reads the arc, not the chord (Breaking.cpp), and
// the solver lab measures it against its own physics, not the 100 N/m springs'.
bool keepsEdgeLengths(std::string_view integrator);

// x += h v for every vertex; shared by all integrators after their velocity update.
void advancePositions(Sheet& sheet, double h, WorkerPool& pool = WorkerPool::serial());

} // namespace pf
