#pragma once

#include "Integrator.h"

namespace pf {

// v += h M⁻¹ f(x, v); x += h v. Cheap, and stable only while h·sqrt(k/m) stays small.
class SymplecticEulerIntegrator final : public Integrator {
  public:
    void advance(Sheet& sheet, const SimParams& params) override;

  private:
    std::vector<Vec3> force_;
};

// Sufficient stability bound for symplectic Euler on this spring network (Gershgorin):
// h ≤ min_i sqrt(2 m_i / Σ_j k_ij) over free vertices. Damping is ignored.
double symplecticStepLimit(const Sheet& sheet, const SimParams& params);

} // namespace pf
