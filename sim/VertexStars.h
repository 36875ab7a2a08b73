#pragma once

#include "Sheet.h"
#include "WorkerPool.h"

#include <vector>

namespace pf {

// For each vertex, the springs and the triangles around it (its star), in ascending id.
// A pass that gathers into a vertex from its star adds in the order a loop over all
// springs (or triangles) scattering into their vertices does, so it gives the same bits,
// and each vertex can be worked out on its own thread (WorkerPool).
class VertexStars {
  public:
    // Brings the stars up to the sheet's connectivity if it is not the one they were built
    // for (compared exactly: any break, hinge, recovery, load or undo changes it):
    // springs appended since are added to the stars, any other change rebuilds them.
    // Returns whether anything changed.
    // The comparison runs on the pool's threads.
    bool refresh(const Sheet& sheet, WorkerPool& pool = WorkerPool::serial());

    // Entry e of vertex i's spring star: spring e >> 1, at whose end b if e & 1, else a.
    const Index* springsBegin(Index i) const { return springs_.data() + springStart_[i]; }
    const Index* springsEnd(Index i) const {
        return springs_.data() + springStart_[i] + springUsed_[i];
    }
    // Triangles of vertex i's star (a triangle twice if it holds i twice).
    const Index* trianglesBegin(Index i) const { return triangles_.data() + triangleStart_[i]; }
    const Index* trianglesEnd(Index i) const { return triangles_.data() + triangleStart_[i + 1]; }

    static Index springOf(Index entry) { return entry >> 1; }
    static bool atEndB(Index entry) { return (entry & 1) != 0; }

    // The vertex count the stars were built for.
    Index vertexCount() const { return static_cast<Index>(springStart_.size()) - 1; }

  private:
    void rebuild(const Sheet& sheet);
    // Puts spring s at the end of its ends' stars; false if one of them is full.
    bool appendSpring(Index s, Index a, Index b);

    // Vertex i's star is springs_[springStart_[i], + springUsed_[i]), with room up to
    // springStart_[i + 1] for springs appended later.
    std::vector<Index> springStart_{0}, springUsed_, springs_;
    std::vector<Index> triangleStart_{0}, triangles_;
    // The connectivity they were built for.
    std::vector<Index> builtA_, builtB_;
    std::vector<Triangle> builtTris_;
};

} // namespace pf
