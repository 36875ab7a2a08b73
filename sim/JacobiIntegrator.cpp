#include "JacobiIntegrator.h"

namespace pf {

void JacobiIntegrator::advance(Sheet& sheet, const SimParams& params) {
    WorkerPool& pool = workers_.poolOrSerial();
    const VertexStars* stars = workers_.stars;
    if (!stars) {
        ownStars_.refresh(sheet);
        stars = &ownStars_;
    }
    system_.assemble(sheet, params, scalar_, pool, *stars);
    const Vec3 gravityStep(0.0, -params.gravity * params.dt, 0.0);
    solveJacobi(sheet, system_, params.iterations, dv_, scratch_, pool, *stars,
                params.gravityOutsideFilter ? &gravityStep : nullptr);
    auto& V = sheet.verts;
    pool.forRanges(V.size(), [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i) V.v[i] += dv_[i];
    });
    advancePositions(sheet, params.dt, pool);
}

} // namespace pf
