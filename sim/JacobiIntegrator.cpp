#include "JacobiIntegrator.h"

namespace pf {

void JacobiIntegrator::advance(Sheet& sheet, const SimParams& params) {
    system_.assemble(sheet, params, scalar_);
    solveJacobi(sheet, system_, params.iterations, dv_, scratch_);
    auto& V = sheet.verts;
    for (Index i = 0; i < V.size(); ++i) V.v[i] += dv_[i];
    advancePositions(sheet, params.dt);
}

} // namespace pf
