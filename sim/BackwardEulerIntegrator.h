#pragma once

#include "ImplicitSystem.h"
#include "Integrator.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

namespace pf {

// The reference: the same linear system as the Jacobi step (Eq. 3), solved to a
// tight tolerance by Eigen's conjugate gradient with a diagonal preconditioner.
class BackwardEulerIntegrator final : public Integrator {
  public:
    void advance(Sheet& sheet, const SimParams& params) override;

    // Relative residual the solve stops at.
    static constexpr double kTolerance = 1e-12;

    // Solves sys exactly (to kTolerance) into dv; returns false if CG did not converge.
    static bool solveExact(const Sheet& sheet, const ImplicitSystem& sys, std::vector<Vec3>& dv);

  private:
    ImplicitSystem system_;
    std::vector<Vec3> dv_;
};

} // namespace pf
