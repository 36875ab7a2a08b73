#pragma once

#include "Types.h"

#include <cstddef>
#include <vector>

namespace pf {

// A distance constraint as one step's sub-steps use it: its ends' inverse masses, its
// rest length, its XPBD gain 1 / (w_a + w_b + α/h²) and the correction its largest pull
// and push allow (lowest ≤ 0 ≤ highest).
struct DistanceConstraint {
    Index a, b;
    double wa, wb, rest, gain, lowest, highest;
};

// The stretch constraints of a step, grouped by colour: no two constraints of a group
// share a vertex, except in groups marked shared (what a greedy colouring could not
// place), which are taken one after another.
class StretchPass {
  public:
    void clear();
    // Appends a constraint; a colour different from the last one's starts a group.
    void add(const DistanceConstraint& k, int colour, bool shared);
    std::size_t size() const { return constraints_.size(); }
    // A forward and then a backward Gauss-Seidel pass, so that a pull travels across the
    // sheet both ways within one sub-step. Bit for bit the passes taken one constraint
    // at a time in order: within a group nothing one constraint writes is read by
    // another, so each group is taken in blocks whose square roots and divisions run
    // two at a time, and overlap, instead of each waiting on the last one's.
    void relax(std::vector<Vec3>& x) const;

  private:
    struct Group {
        std::size_t begin, end;
        bool shared;
    };
    void relaxGroup(const Group& g, std::vector<Vec3>& x) const;
    void relaxInOrder(std::size_t q, std::vector<Vec3>& x) const;

    std::vector<DistanceConstraint> constraints_;
    std::vector<Group> groups_;
    int lastColour_ = -1;
};

} // namespace pf
