#pragma once

#include "Params.h"
#include "Sheet.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace pf {

// Advances velocities and positions of a sheet by one step of length params.dt.
// Pinned vertices keep the velocity the scene script gave them and move with it.
// An integrator owns its scratch memory, so a step allocates nothing once warm.
class Integrator {
  public:
    virtual ~Integrator() = default;
    virtual void advance(Sheet& sheet, const SimParams& params) = 0;
};

// Names: "jacobi" (Eq. 6, 3×3 blocks), "jacobi-scalar" (Eq. 6, k·I blocks),
// "symplectic" (symplectic Euler), "backward-euler" (Eq. 3 solved by conjugate gradient).
// Returns nullptr for an unknown name.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);
const std::vector<std::string>& integratorNames();

// x += h v for every vertex; shared by all integrators after their velocity update.
void advancePositions(Sheet& sheet, double h);

} // namespace pf
