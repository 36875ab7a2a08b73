#pragma once

#include "SymmetricAmdOrdering.h"
#include "Types.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace pf {

// A sparse LDLT factorisation applied to one 3-vector per unknown: the same scalar
// matrix for x, y and z (bending and gravity act alike on each coordinate). Eigen's
// SimplicialLDLT solves an n×3 right-hand side one column at a time, walking the factor
// three times through strided memory; this walks it once, with the three coordinates
// side by side. The arithmetic is Eigen's, operation for operation, so the result is
// bit-identical to solver.solve() on the n×3 matrix (test_solvers checks it).
class VectorLdlt {
  public:
    // Factors a; false if the factorisation failed (a not positive definite).
    bool compute(const Eigen::SparseMatrix<double>& a);
    // x = A⁻¹ b, for b and x of the factored size (they may be the same vector).
    void solve(const std::vector<Vec3>& b, std::vector<Vec3>& x) const;
    Index size() const { return static_cast<Index>(diagonalInverse_.size()); }

  private:
    SymmetricLdlt ldlt_;
    std::vector<Index> permutation_;        // row i of b goes to row permutation_[i]
    std::vector<Index> inversePermutation_; // and back
    std::vector<double> diagonalInverse_;   // 1 / D, as Eigen multiplies by it
    mutable std::vector<Vec3> work_;
};

// y = Q x for a symmetric sparse Q applied to each coordinate, in the order Eigen's
// sparse × dense product adds its terms (bit-identical to Q * X on an n×3 X).
void multiplyEachCoordinate(const Eigen::SparseMatrix<double>& q, const std::vector<Vec3>& x,
                            std::vector<Vec3>& y);

} // namespace pf
