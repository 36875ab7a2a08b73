#pragma once

#include "ImplicitSystem.h"
#include "Integrator.h"

namespace pf {

// The paper's approximate implicit step: Eq. 3 solved by params.iterations Jacobi
// sweeps after the initial estimate (Eq. 6).
class JacobiIntegrator final : public Integrator {
  public:
    explicit JacobiIntegrator(bool scalarBlocks) : scalar_(scalarBlocks) {}
    void advance(Sheet& sheet, const SimParams& params) override;
    void lendWorkers(const StepWorkers& workers) override { workers_ = workers; }
    bool boundsStretch() const override { return false; }

  private:
    bool scalar_;
    StepWorkers workers_;
    VertexStars ownStars_; // without lent ones
    ImplicitSystem system_;
    std::vector<Vec3> dv_, scratch_;
};

} // namespace pf
