#pragma once

#include "Types.h"

#include <Eigen/SparseCore>
#include <span>
#include <utility>

namespace pf {

// An active stretch constraint met at a vertex: its index among the active constraints
// and the sign of the vertex in it (+1 at its first end, −1 at its second).
struct ConstraintAtVertex {
    Index constraint;
    double sign;
};

// The matrix of the fast projection's Newton step over the active stretch constraints,
// J W Jᵀ + ε diag(w_a + w_b): every free vertex i couples each two constraints e, f that
// meet there by w_i s_e s_f d_e · d_f (d the constraints' directions), and ε regularises
// the diagonal. Only the lower triangle is written, column-major, compressed, rows sorted
// in each column: what the LDLT reads. Each entry sums its vertices' terms in the order of
// the vertices, then ε, which is the order Eigen's setFromTriplets summed them in when the
// projection listed every vertex's d × d block, so the values are the same, bit for bit,
// at a fraction of the cost (no triplets, no sort, no transposed copy, half the entries).
//
// ends[e] are constraint e's two vertices; incidentStart/incident list, for each vertex,
// the constraints met there in increasing order (incident[incidentStart[i]] onwards).
void assembleProjectionSystem(std::span<const std::pair<Index, Index>> ends,
                              std::span<const Vec3> directions, std::span<const double> w,
                              std::span<const Index> incidentStart,
                              std::span<const ConstraintAtVertex> incident, double compliance,
                              Eigen::SparseMatrix<double>& lower);

} // namespace pf
