#pragma once

#include "Params.h"
#include "Sheet.h"
#include "VertexStars.h"
#include "WorkerPool.h"

#include <vector>

namespace pf {

// A spring's coupling block G = axial·uuᵀ + iso·I (symmetric, 5 numbers instead of 9).
struct Coupling {
    Vec3 u = Vec3::Zero();
    double axial = 0.0;
    double iso = 0.0;

    Vec3 apply(const Vec3& x) const { return axial * u.dot(x) * u + iso * x; }
    Mat3 matrix() const { return axial * u * u.transpose() + iso * Mat3::Identity(); }
};

// The linear system of one linearised backward Euler step (paper Eq. 3-4):
//   A Δv = b,   A = M - h ∂f/∂v - h² ∂f/∂x,   b = h (f + h ∂f/∂x v) = h f̃
// stored the way the spring network makes it: one coupling block G_s = h² K_s + h C_s
// per spring (A_ab = A_ba = -G_s) and one diagonal block W_i = m_i I + Σ G_s per
// vertex. Every solver (Jacobi sweeps, conjugate gradient, the lab's error metrics)
// reads this one assembly, so they all solve the same system.
//
// Pinned vertices get W = I and b = 0: their Δv is zero and the scene script
// drives them, so they act as infinite masses to their neighbours.
struct ImplicitSystem {
    std::vector<Coupling> coupling; // per spring
    std::vector<Mat3> diag;         // per vertex
    std::vector<Mat3> diagInv;      // per vertex, W_i^-1
    std::vector<Vec3> rhs;          // per vertex, b_i
    // Per spring: what it adds to b at its end a (its end b gets the opposite).
    std::vector<Vec3> springRhs;

    // scalar: the Kang & Cho 2004 simplification, every block k·I and c·I (no direction).
    // The springs' blocks are worked out on the pool's threads, then each vertex gathers
    // its own from its star: the same bits on any number of threads.
    void assemble(const Sheet& sheet, const SimParams& params, bool scalar, WorkerPool& pool,
                  const VertexStars& stars);
    // On one thread, with stars of its own.
    void assemble(const Sheet& sheet, const SimParams& params, bool scalar);

    // y = A x.
    void multiply(const Sheet& sheet, const std::vector<Vec3>& x, std::vector<Vec3>& y) const;

  private:
    VertexStars ownStars_; // for the one-thread assemble
};

// One Jacobi sweep of Eq. 6: out_i = W_i^-1 (b_i + Σ_j G_ij in_j).
void jacobiSweep(const Sheet& sheet, const ImplicitSystem& sys, const std::vector<Vec3>& in,
                 std::vector<Vec3>& out, WorkerPool& pool, const VertexStars& stars);

// Eq. 6 with `sweeps` sweeps after the initial estimate. The initial estimate is
// itself one sweep, from 0 (the paper: Δv⁽⁰⁾ = W_i^-1 b_i) or, with `start`, from
// that guess (free vertices only; pinned ones stay 0).
void solveJacobi(const Sheet& sheet, const ImplicitSystem& sys, int sweeps, std::vector<Vec3>& dv,
                 std::vector<Vec3>& scratch, WorkerPool& pool, const VertexStars& stars,
                 const Vec3* start = nullptr);
// On one thread, with stars built for the call.
void solveJacobi(const Sheet& sheet, const ImplicitSystem& sys, int sweeps, std::vector<Vec3>& dv,
                 std::vector<Vec3>& scratch, const Vec3* start = nullptr);

} // namespace pf
