#include "ImplicitSystem.h"

#include "SpringForce.h"

namespace pf {

void ImplicitSystem::assemble(const Sheet& sheet, const SimParams& params, bool scalar) {
    const auto& V = sheet.verts;
    const auto& S = sheet.springs;
    const Index nv = V.size();
    const Index ns = S.size();
    const double h = params.dt;
    coupling.resize(ns);
    diag.resize(nv);
    diagInv.resize(nv);
    rhs.resize(nv);

    const Vec3 gravity(0.0, -params.gravity, 0.0);
    for (Index i = 0; i < nv; ++i) {
        diag[i] = V.m[i] * Mat3::Identity();
        rhs[i] = h * V.m[i] * gravity; // h f (gravity part)
    }

    const double h2 = h * h;
    for (Index s = 0; s < ns; ++s) {
        const Index a = S.a[s], b = S.b[s];
        const double k = params.stiffnessOf(S.kind[s]);
        const double c = params.dampingOf(S.kind[s]);
        const SpringTerms t =
            springTerms(V.x[a], V.x[b], V.v[a], V.v[b], S.rest[s], k, c, params.clampCompressed);
        // K = k(1 - t) uuᵀ + k t I and C = c uuᵀ; the scalar variant uses k I and c I.
        Coupling& G = coupling[s];
        G.u = t.u;
        const double kAxial = scalar ? 0.0 : k * (1.0 - t.transverse);
        const double kIso = scalar ? k : k * t.transverse;
        G.axial = h2 * kAxial + (scalar ? 0.0 : h * c);
        G.iso = h2 * kIso + (scalar ? h * c : 0.0);
        if (!t.valid) G.axial = 0.0; // no direction: only the isotropic part is defined
        const Mat3 Gm = G.matrix();
        diag[a] += Gm;
        diag[b] += Gm;
        // b = h f + h² K_ab (v_b - v_a) for a, and the mirror for b.
        const Vec3 dvab = V.v[b] - V.v[a];
        const Vec3 term = h * t.force * t.u + h2 * (kAxial * t.u.dot(dvab) * t.u + kIso * dvab);
        rhs[a] += term;
        rhs[b] -= term;
    }

    for (Index i = 0; i < nv; ++i) {
        if (V.pinned[i]) {
            diag[i].setIdentity();
            rhs[i].setZero();
        }
        diagInv[i] = diag[i].inverse();
    }
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
                 std::vector<Vec3>& out) {
    const auto& S = sheet.springs;
    const auto& pinned = sheet.verts.pinned;
    const Index nv = sheet.verts.size();
    out.resize(nv);
    for (Index i = 0; i < nv; ++i) out[i] = sys.rhs[i];
    for (Index s = 0; s < S.size(); ++s) {
        const Index a = S.a[s], b = S.b[s];
        out[a] += sys.coupling[s].apply(in[b]);
        out[b] += sys.coupling[s].apply(in[a]);
    }
    for (Index i = 0; i < nv; ++i)
        out[i] = pinned[i] ? Vec3::Zero() : Vec3(sys.diagInv[i] * out[i]);
}

void solveJacobi(const Sheet& sheet, const ImplicitSystem& sys, int sweeps, std::vector<Vec3>& dv,
                 std::vector<Vec3>& scratch, const Vec3* start) {
    const Index nv = sheet.verts.size();
    dv.resize(nv);
    if (start) {
        for (Index i = 0; i < nv; ++i) dv[i] = sheet.verts.pinned[i] ? Vec3::Zero() : *start;
        ++sweeps; // the initial estimate is a sweep from the guess
    } else {
        for (Index i = 0; i < nv; ++i) dv[i] = sys.diagInv[i] * sys.rhs[i];
    }
    for (int k = 0; k < sweeps; ++k) {
        jacobiSweep(sheet, sys, dv, scratch);
        dv.swap(scratch);
    }
}

} // namespace pf
