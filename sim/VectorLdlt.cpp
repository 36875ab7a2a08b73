#include "VectorLdlt.h"

namespace pf {

bool VectorLdlt::compute(const Eigen::SparseMatrix<double>& a) {
    ldlt_.compute(a);
    if (ldlt_.info() != Eigen::Success) {
        diagonalInverse_.clear();
        return false;
    }
    const Index n = a.rows();
    permutation_.assign(static_cast<std::size_t>(n), 0);
    inversePermutation_.assign(static_cast<std::size_t>(n), 0);
    const auto& p = ldlt_.permutationP().indices();
    const auto& pinv = ldlt_.permutationPinv().indices();
    for (Index i = 0; i < n; ++i) {
        permutation_[i] = p.size() > 0 ? p[i] : i;
        inversePermutation_[i] = pinv.size() > 0 ? pinv[i] : i;
    }
    // Eigen computes D⁻¹ x as (1 / d) · x, and so does solve() below.
    diagonalInverse_.resize(static_cast<std::size_t>(n));
    const auto& d = ldlt_.vectorD();
    for (Index i = 0; i < n; ++i) diagonalInverse_[i] = Eigen::numext::real(1.0 / d[i]);
    return true;
}

void VectorLdlt::solve(const std::vector<Vec3>& b, std::vector<Vec3>& x) const {
    const Index n = size();
    work_.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) work_[permutation_[i]] = b[i];
    // L is unit lower triangular, stored by columns.
    const Eigen::SparseMatrix<double>& l = ldlt_.matrixL().nestedExpression();
    const int* start = l.outerIndexPtr();
    const int* row = l.innerIndexPtr();
    const double* value = l.valuePtr();
    const int* nonZeros = l.innerNonZeroPtr(); // null when compressed
    const auto end = [&](Index j) { return nonZeros ? start[j] + nonZeros[j] : start[j + 1]; };
    for (Index j = 0; j < n; ++j) {
        const Vec3 t = work_[j];
        int k = start[j];
        const int e = end(j);
        while (k < e && row[k] < j) ++k;
        if (k < e && row[k] == j) ++k;
        for (; k < e; ++k) {
            Vec3& w = work_[row[k]];
            // Eigen skips a zero column of the right-hand side; t·value is then ±0,
            // which leaves every nonzero entry as it is.
            w[0] -= t[0] * value[k];
            w[1] -= t[1] * value[k];
            w[2] -= t[2] * value[k];
        }
    }
    for (Index i = 0; i < n; ++i) work_[i] = diagonalInverse_[i] * work_[i];
    // Lᵀ: row j of the upper factor is column j of L.
    for (Index j = n - 1; j >= 0; --j) {
        Vec3 t = work_[j];
        int k = start[j];
        const int e = end(j);
        while (k < e && row[k] < j) ++k;
        if (k < e && row[k] == j) ++k;
        for (; k < e; ++k) {
            const Vec3& w = work_[row[k]];
            t[0] -= value[k] * w[0];
            t[1] -= value[k] * w[1];
            t[2] -= value[k] * w[2];
        }
        work_[j] = t;
    }
    x.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) x[inversePermutation_[i]] = work_[i];
}

void multiplyEachCoordinate(const Eigen::SparseMatrix<double>& q, const std::vector<Vec3>& x,
                            std::vector<Vec3>& y) {
    const Index n = q.rows();
    y.assign(static_cast<std::size_t>(n), Vec3::Zero());
    for (Index j = 0; j < q.outerSize(); ++j) {
        const Vec3 xj = x[j];
        for (Eigen::SparseMatrix<double>::InnerIterator it(q, j); it; ++it) {
            Vec3& yi = y[it.index()];
            yi[0] += it.value() * xj[0];
            yi[1] += it.value() * xj[1];
            yi[2] += it.value() * xj[2];
        }
    }
}

} // namespace pf
