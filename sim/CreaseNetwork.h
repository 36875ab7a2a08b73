#pragma once

#include "Sheet.h"

#include <vector>

namespace pf {

// The creases a sheet's breaks have drawn, measured on the flat paper (in material
// coordinates), as experiments measure a crumpled sheet flattened again. A break of
// e_ij inserts n and lifts or sinks it (Eq. 11): the paper then bends along r–n–l,
// across the broken edge, so those two new edges are the break's piece of crease.
struct CreaseNetwork {
    double totalLength = 0.0;     // m
    std::vector<double> segments; // m, each a run of crease edges (below), longest first
};

// A run goes on through a vertex where exactly two crease edges meet and turn by less
// than this; it ends at a junction, at an end or at a corner (a ridge of a crumpled
// sheet runs from one vertex of the network to the next: Andresen et al. 2007).
inline constexpr double kCreaseRunMaxTurn = 1.0471975511965976; // 60°, in radians

// The crease edges r–n and n–l of every active break, with their material lengths.
struct CreaseEdge {
    Index a, b;
    double length; // m
};
std::vector<CreaseEdge> creaseEdges(const Sheet& sheet);

CreaseNetwork measureCreases(const Sheet& sheet);

} // namespace pf
