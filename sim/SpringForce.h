#pragma once

#include "Types.h"

#include <algorithm>

namespace pf {

// Force of one damped Hooke spring on its end a (the force on b is the negative)
// and its derivatives. With u = (x_b - x_a)/l:
//   f_a = k (l - L) u + c ((v_b - v_a)·u) u
//   K   = ∂f_a/∂x_b = k [u uᵀ + t (I - u uᵀ)],  t = 1 - L/l   (∂f_a/∂x_a = -K)
//   C   = ∂f_a/∂v_b = c u uᵀ                                   (∂f_a/∂v_a = -C)
// The damping force's dependence on x is left out of K, as in Baraff & Witkin.
// With clampCompressed, t = max(0, 1 - L/l), so K stays positive semidefinite when
// the spring is shorter than its rest length (its transverse term is otherwise negative).
//
// Every block is a·uuᵀ + b·I, so the step stores (u, a, b) instead of 3×3 matrices.
struct SpringTerms {
    Vec3 u = Vec3::Zero();   // unit direction a -> b
    double force = 0.0;      // signed magnitude along u of the force on a
    double transverse = 0.0; // t
    bool valid = false;      // false for coincident ends: no direction, no force
};

inline SpringTerms springTerms(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                               double rest, double stiffness, double damping,
                               bool clampCompressed) {
    SpringTerms s;
    const Vec3 d = xb - xa;
    const double l = d.norm();
    if (!(l > 1e-14)) return s;
    s.valid = true;
    s.u = d / l;
    s.force = stiffness * (l - rest) + damping * (vb - va).dot(s.u);
    s.transverse = 1.0 - rest / l;
    if (clampCompressed) s.transverse = std::max(0.0, s.transverse);
    return s;
}

// The same as full matrices, for tests and tools that want them.
struct SpringEval {
    Vec3 force = Vec3::Zero();
    Mat3 K = Mat3::Zero();
    Mat3 C = Mat3::Zero();
};

SpringEval evaluateSpring(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                          double rest, double stiffness, double damping, bool clampCompressed);

} // namespace pf
