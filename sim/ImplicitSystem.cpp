#include "ImplicitSystem.h"

#include "SpringForce.h"

namespace pf {

void ImplicitSystem::assemble(const Sheet& sheet, const SimParams& params, bool scalar,
                              WorkerPool& pool, const VertexStars& stars) {
    const auto& V = sheet.verts;
    const auto& S = sheet.springs;
    const Index nv = V.size();
    const Index ns = S.size();
    const double h = params.dt;
    coupling.resize(ns);
    springRhs.resize(ns);
    diag.resize(nv);
    diagInv.resize(nv);
    rhs.resize(nv);

    const double h2 = h * h;
    pool.forRanges(ns, [&](Index begin, Index end) {
        for (Index s = begin; s < end; ++s) {
            const Index a = S.a[s], b = S.b[s];
            const double k = params.stiffnessOf(S.kind[s]);
            const double c = params.dampingOf(S.kind[s]);
            const SpringTerms t = springTerms(V.x[a], V.x[b], V.v[a], V.v[b], S.rest[s], k, c,
                                              params.clampCompressed);
            // K = k(1 - t) uuᵀ + k t I and C = c uuᵀ; the scalar variant uses k I and c I.
            Coupling& G = coupling[s];
            G.u = t.u;
            const double kAxial = scalar ? 0.0 : k * (1.0 - t.transverse);
            const double kIso = scalar ? k : k * t.transverse;
            G.axial = h2 * kAxial + (scalar ? 0.0 : h * c);
            G.iso = h2 * kIso + (scalar ? h * c : 0.0);
            if (!t.valid) G.axial = 0.0; // no direction: only the isotropic part is defined
            // b = h f + h² K_ab (v_b - v_a) for a, and the mirror for b.
            const Vec3 dvab = V.v[b] - V.v[a];
            springRhs[s] = h * t.force * t.u + h2 * (kAxial * t.u.dot(dvab) * t.u + kIso * dvab);
        }
    });

    // W_i = m_i I + Σ G_s and b_i = h m_i g ± Σ springRhs, each vertex from its star.
    const Vec3 gravity(0.0, -params.gravity, 0.0);
    pool.forRanges(nv, [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i) {
            if (V.pinned[i]) {
                diag[i].setIdentity();
                rhs[i].setZero();
                diagInv[i].setIdentity();
                continue;
            }
            Mat3 W = V.m[i] * Mat3::Identity();
            Vec3 b = h * V.m[i] * gravity; // h f (gravity part)
            for (const Index* e = stars.springsBegin(i); e != stars.springsEnd(i); ++e) {
                const Index s = VertexStars::springOf(*e);
                W += coupling[s].matrix();
                if (VertexStars::atEndB(*e))
                    b -= springRhs[s];
                else
                    b += springRhs[s];
            }
            diag[i] = W;
            rhs[i] = b;
            diagInv[i] = W.inverse();
        }
    });
}

void ImplicitSystem::assemble(const Sheet& sheet, const SimParams& params, bool scalar) {
    ownStars_.refresh(sheet);
    assemble(sheet, params, scalar, WorkerPool::serial(), ownStars_);
}

void ImplicitSystem::multiply(const Sheet& sheet, const std::vector<Vec3>& x,
                              std::vector<Vec3>& y) const {
    const auto& S = sheet.springs;
    const auto& pinned = sheet.verts.pinned;
    const Index nv = sheet.verts.size();
    y.resize(nv);
    for (Index i = 0; i < nv; ++i) y[i] = diag[i] * x[i];
    for (Index s = 0; s < S.size(); ++s) {
        const Index a = S.a[s], b = S.b[s];
        if (pinned[a] || pinned[b]) continue; // pinned rows and columns are identity
        y[a] -= coupling[s].apply(x[b]);
        y[b] -= coupling[s].apply(x[a]);
    }
}

void jacobiSweep(const Sheet& sheet, const ImplicitSystem& sys, const std::vector<Vec3>& in,
                 std::vector<Vec3>& out, WorkerPool& pool, const VertexStars& stars) {
    const auto& S = sheet.springs;
    const auto& pinned = sheet.verts.pinned;
    const Index nv = sheet.verts.size();
    out.resize(nv);
    pool.forRanges(nv, [&](Index begin, Index end) {
        for (Index i = begin; i < end; ++i) {
            if (pinned[i]) {
                out[i].setZero();
                continue;
            }
            Vec3 sum = sys.rhs[i];
            for (const Index* e = stars.springsBegin(i); e != stars.springsEnd(i); ++e) {
                const Index s = VertexStars::springOf(*e);
                const Index other = VertexStars::atEndB(*e) ? S.a[s] : S.b[s];
                sum += sys.coupling[s].apply(in[other]);
            }
            out[i] = sys.diagInv[i] * sum;
        }
    });
}

void solveJacobi(const Sheet& sheet, const ImplicitSystem& sys, int sweeps, std::vector<Vec3>& dv,
                 std::vector<Vec3>& scratch, WorkerPool& pool, const VertexStars& stars,
                 const Vec3* start) {
    const Index nv = sheet.verts.size();
    dv.resize(nv);
    if (start) {
        for (Index i = 0; i < nv; ++i) dv[i] = sheet.verts.pinned[i] ? Vec3::Zero() : *start;
        ++sweeps; // the initial estimate is a sweep from the guess
    } else {
        pool.forRanges(nv, [&](Index begin, Index end) {
            for (Index i = begin; i < end; ++i) dv[i] = sys.diagInv[i] * sys.rhs[i];
        });
    }
    for (int k = 0; k < sweeps; ++k) {
        jacobiSweep(sheet, sys, dv, scratch, pool, stars);
        dv.swap(scratch);
    }
}

void solveJacobi(const Sheet& sheet, const ImplicitSystem& sys, int sweeps, std::vector<Vec3>& dv,
                 std::vector<Vec3>& scratch, const Vec3* start) {
    VertexStars stars;
    stars.refresh(sheet);
    solveJacobi(sheet, sys, sweeps, dv, scratch, WorkerPool::serial(), stars, start);
}

} // namespace pf
