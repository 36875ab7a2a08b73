#pragma once

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace pf {

// Eigen's approximate minimum degree ordering for the matrices SimplicialLDLT orders.
// SimplicialLDLT hands its ordering the whole symmetric matrix, written out (sorted)
// from the triangle it reads, and Eigen's AMDOrdering then builds Aᵀ + A of it again,
// a transpose and a sparse sum: 6 % of a step that projects a pinned crumpled sheet
// (docs/speed.md). Here the symmetric pattern goes to the ordering as it is. It is the
// pattern Aᵀ + A would have, column by column in the same order, so the ordering is the
// same, bit for bit (test_solvers checks it).
template <typename StorageIndex> class SymmetricAmdOrdering {
  public:
    using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, StorageIndex>;

    template <typename MatrixType>
    void operator()(const MatrixType& symmetric, PermutationType& perm) {
        // The ordering uses the matrix's storage as its workspace.
        Eigen::SparseMatrix<typename MatrixType::Scalar, Eigen::ColMajor, StorageIndex> work =
            symmetric;
        Eigen::internal::minimum_degree_ordering(work, perm);
    }
};

// A sparse LDLT of a symmetric matrix of which it reads the lower triangle, ordered as
// Eigen's default orders it.
using SymmetricLdlt =
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, SymmetricAmdOrdering<int>>;

} // namespace pf
