#pragma once

#include "Sheet.h"

#include <array>
#include <cstdint>
#include <tuple>
#include <vector>

namespace pf {

// Contact of the paper with itself: layers of a fold or a crumple lie on each other,
// a sheet's thickness apart, and slide on each other with paper-on-paper friction.
// Each vertex is kept on the side of every triangle it was on when the step began,
// so it cannot pass through a layer it could reach within the step (the pairs
// are found once per step, for everything that can meet in it, from the state alone:
// a run resumed from a file finds the same).
class SelfContact {
  public:
    // Finds the vertex-triangle pairs that can touch before a vertex has moved farther
    // than its `allowance` from where it is now: a free vertex within the thickness plus
    // its own and the triangle's corners' allowances of a triangle. A triangle with a
    // corner in the ring of triangles round the vertex is its own paper bending, not a
    // contact, nor is paper within `apart` of it in the material. Pairs are in triangle
    // order, then by the first cell of the search's grid the vertex and the triangle
    // share, then by vertex: the same sheet gives the same pairs in the same order.
    // `bucketCells` sets the hash's buckets (cells a side; 0: from the allowances), which
    // change only the time it takes; -1 walks cell by cell and keeps the walk's order, as
    // the search did before it had buckets (for tests).
    void find(const Sheet& sheet, const std::vector<double>& inverseMass, double thickness,
              const std::vector<double>& allowance, double apart, int bucketCells = 0);
    // Pushes every pair that is closer than the thickness apart back to it, the vertex
    // and the triangle's corners by their inverse masses, but a pair already that close
    // at `previous` (or through) at most `maxSeparation` farther apart than it was. With
    // friction, the slip of the vertex over the triangle since `previous` is undone while
    // it is within μs times the push, else cut by μk times it.
    void resolve(std::vector<Vec3>& x, const std::vector<Vec3>& previous,
                 const std::vector<double>& inverseMass, double staticFriction,
                 double kineticFriction, bool withFriction, double maxSeparation);
    struct Pair {
        Index vertex, triangle;
        std::array<Index, 3> corners; // the triangle's, as it was found
        double side;                  // +1: on the side the triangle's normal points to
        // How far the two could have moved toward each other since they were found: a
        // vertex deeper than this on the other side came round the layer's edge, not
        // through it, and is left there.
        double depth;
    };
    const std::vector<Pair>& pairs() const { return pairs_; }
    // The pairs whose vertex now lies on the other side of its triangle (its foot still
    // in it) than when they were found: paper that went through paper.
    std::size_t crossed(const std::vector<Vec3>& x) const;

  private:
    std::vector<Pair> pairs_;
    double thickness_ = 0.0;
    std::vector<Index> seenBy_; // the triangle that tried the vertex last
    // A box's cells of the search's grid, lowest and highest along x, y and z.
    struct CellRange {
        std::array<std::int64_t, 3> lo, hi;
    };
    std::vector<CellRange> vertexCells_;
    // A triangle's pairs as they are found, with the first cell each shares with it.
    struct Found {
        std::tuple<std::int64_t, std::int64_t, std::int64_t, Index> order;
        Pair pair;
    };
    std::vector<Found> found_;
    // The free vertices' buckets of the hash: (bucket key, vertex), sorted by key.
    std::vector<std::pair<std::uint64_t, Index>> cells_;
    struct Slot {
        std::uint64_t key = 0;
        Index begin = 0, end = 0; // the cell's run in cells_; end 0: an empty slot
    };
    std::vector<Slot> slots_;
    // resolve(): when each vertex last moved, by a clock that ticks at every move and
    // every normal worked out.
    std::vector<std::uint64_t> movedAt_;
    std::uint64_t clock_ = 0;
    // The triangles round each vertex, vertex by vertex.
    std::vector<Index> ringStart_, ring_, ringFill_;
};

} // namespace pf
