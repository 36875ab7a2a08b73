#include "JacobiIntegrator.h"

namespace pf {

void JacobiIntegrator::advance(Sheet& sheet, const SimParams& params) {
    system_.assemble(sheet, params, scalar_);
    const Vec3 gravityStep(0.0, -params.gravity * params.dt, 0.0);
    solveJacobi(sheet, system_, params.iterations, dv_, scratch_,
                params.gravityOutsideFilter ? &gravityStep : nullptr);
    auto& V = sheet.verts;
    for (Index i = 0; i < V.size(); ++i) V.v[i] += dv_[i];
    advancePositions(sheet, params.dt);
}

} // namespace pf
