#include "SymplecticEulerIntegrator.h"

#include "SpringForce.h"

#include <cmath>
#include <limits>

namespace pf {

void SymplecticEulerIntegrator::advance(Sheet& sheet, const SimParams& params) {
    auto& V = sheet.verts;
    const auto& S = sheet.springs;
    const Index nv = V.size();
    force_.resize(nv);
    const Vec3 gravity(0.0, -params.gravity, 0.0);
    for (Index i = 0; i < nv; ++i) force_[i] = V.m[i] * gravity;
    for (Index s = 0; s < S.size(); ++s) {
        const Index a = S.a[s], b = S.b[s];
        const SpringTerms t =
            springTerms(V.x[a], V.x[b], V.v[a], V.v[b], S.rest[s], params.stiffnessOf(S.kind[s]),
                        params.dampingOf(S.kind[s]), params.clampCompressed);
        const Vec3 f = t.force * t.u;
        force_[a] += f;
        force_[b] -= f;
    }
    for (Index i = 0; i < nv; ++i)
        if (!V.pinned[i]) V.v[i] += (params.dt / V.m[i]) * force_[i];
    advancePositions(sheet, params.dt);
}

double symplecticStepLimit(const Sheet& sheet, const SimParams& params) {
    const auto& V = sheet.verts;
    const auto& S = sheet.springs;
    std::vector<double> stiffnessSum(static_cast<std::size_t>(V.size()), 0.0);
    for (Index s = 0; s < S.size(); ++s) {
        const double k = params.stiffnessOf(S.kind[s]);
        stiffnessSum[S.a[s]] += k;
        stiffnessSum[S.b[s]] += k;
    }
    double limit = std::numeric_limits<double>::infinity();
    for (Index i = 0; i < V.size(); ++i)
        if (!V.pinned[i] && stiffnessSum[i] > 0.0)
            limit = std::min(limit, std::sqrt(2.0 * V.m[i] / stiffnessSum[i]));
    return limit;
}

} // namespace pf
