#pragma once

#include "Sheet.h"

#include <vector>

namespace pf {

// Paper that does not stretch (keepsEdgeLengths) settles the paper round the vertices a
// break pass inserted, before the next step: a break across a cell that the fold had
// sheared cannot give all four new edges their rest lengths by placing n alone (breakEdge
// shares the excess among them), and the step after it measured 3-20 % stretch there
// while a second fold crossed the first. Stretched structural edges that touch a new
// vertex or the two rings of vertices round it are shortened to their rest lengths by
// Gauss-Seidel sweeps that move only those vertices (the paper beyond them, and pins,
// stay), so what is left spreads over the crease's rings instead of one edge. Velocities stay: the
// move is the settling a real crease does within the step. Vertices from `firstNew` on
// are the new ones; returns the vertices it may have moved.
std::vector<Index> relaxAroundNewVertices(Sheet& sheet, Index firstNew);

} // namespace pf
