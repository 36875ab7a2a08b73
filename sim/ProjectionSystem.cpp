#include "ProjectionSystem.h"

#include <algorithm>

namespace pf {

namespace {

// The constraints met at a vertex, from the first one at or after `from`, and the sign
// of the vertex in the constraint whose column is being written.
struct VertexRun {
    const ConstraintAtVertex* at = nullptr;
    const ConstraintAtVertex* end = nullptr;
    double weight = 0.0;     // the vertex's inverse mass
    double columnSign = 0.0; // the sign of the vertex in the column's constraint

    VertexRun(std::span<const Index> incidentStart, std::span<const ConstraintAtVertex> incident,
              Index vertex, Index from, double w, double sign)
        : weight(w), columnSign(sign) {
        if (w == 0.0) return; // a pinned vertex couples nothing
        const ConstraintAtVertex* first = incident.data() + incidentStart[vertex];
        end = incident.data() + incidentStart[vertex + 1];
        at = std::lower_bound(first, end, from, [](const ConstraintAtVertex& c, Index f) {
            return c.constraint < f;
        });
    }
    bool done() const { return at == end; }
    Index row() const { return at->constraint; }
    double term(std::span<const Vec3> d, Index column) const {
        return weight * at->sign * columnSign * d[at->constraint].dot(d[column]);
    }
};

// Calls emit(row, value) for the entries of column f on and below the diagonal, rows in
// increasing order.
template <typename Emit>
void forEachEntry(Index f, std::span<const std::pair<Index, Index>> ends, std::span<const Vec3> d,
                  std::span<const double> w, std::span<const Index> incidentStart,
                  std::span<const ConstraintAtVertex> incident, double compliance, Emit&& emit) {
    const auto [a, b] = ends[f];
    // The lower-numbered vertex first: setFromTriplets summed the vertices in order.
    const Index lo = std::min(a, b), hi = std::max(a, b);
    VertexRun first(incidentStart, incident, lo, f, w[lo], lo == a ? 1.0 : -1.0);
    VertexRun second(incidentStart, incident, hi, f, w[hi], hi == a ? 1.0 : -1.0);
    const double diagonalTerm = compliance * (w[a] + w[b]);
    const bool diagonalListed =
        (!first.done() && first.row() == f) || (!second.done() && second.row() == f);
    if (!diagonalListed) emit(f, diagonalTerm); // both ends pinned: ε alone
    while (!first.done() || !second.done()) {
        const bool takeFirst = !first.done() && (second.done() || first.row() <= second.row());
        const bool takeSecond = !second.done() && (first.done() || second.row() <= first.row());
        const Index row = takeFirst ? first.row() : second.row();
        double value = takeFirst ? first.term(d, f) : second.term(d, f);
        if (takeFirst && takeSecond) value += second.term(d, f);
        if (row == f) value += diagonalTerm;
        emit(row, value);
        if (takeFirst) ++first.at;
        if (takeSecond) ++second.at;
    }
}

} // namespace

void assembleProjectionSystem(std::span<const std::pair<Index, Index>> ends,
                              std::span<const Vec3> directions, std::span<const double> w,
                              std::span<const Index> incidentStart,
                              std::span<const ConstraintAtVertex> incident, double compliance,
                              Eigen::SparseMatrix<double>& lower) {
    const Index n = static_cast<Index>(ends.size());
    // A column has at most the constraints met at its two vertices: room for that many,
    // then the columns written one after another, and the room left over given back.
    Index room = 0;
    for (std::size_t v = 0; v + 1 < incidentStart.size(); ++v) {
        const Index degree = incidentStart[v + 1] - incidentStart[v];
        room += degree * degree;
    }
    lower.resize(n, n);
    lower.resizeNonZeros(room + n);
    Index* outer = lower.outerIndexPtr();
    Index* rows = lower.innerIndexPtr();
    double* values = lower.valuePtr();
    Index k = 0;
    outer[0] = 0;
    for (Index f = 0; f < n; ++f) {
        forEachEntry(f, ends, directions, w, incidentStart, incident, compliance,
                     [&](Index row, double value) {
                         rows[k] = row;
                         values[k] = value;
                         ++k;
                     });
        outer[f + 1] = k;
    }
    lower.resizeNonZeros(k);
}

} // namespace pf
