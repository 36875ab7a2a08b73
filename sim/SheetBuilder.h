#pragma once

#include "Sheet.h"

namespace pf {

// A flat rectangular sheet in the x-z plane at height y, centred on the y axis.
struct SheetSpec {
    double width = 0.210;  // along x (A4 short side), metres
    double length = 0.297; // along z (A4 long side), metres
    int columns = 19;      // vertices along x
    int rows = 26;         // vertices along z
    double density = 0.08; // kg/m^2 (80 g/m^2)
    double height = 0.0;
};

// A4 at `resolution` vertices along the short side, the long side keeping the ratio.
// resolution 19 gives 19 × 26 = 494 vertices, the paper's Fig. 13 count.
SheetSpec a4Spec(int resolution);
// Any rectangle at `resolution` vertices along its width (x), rows keeping the ratio.
SheetSpec sizedSpec(int resolution, double width, double length);

// Grid triangulated with alternating diagonals (no preferred direction), masses
// lumped from rest areas, structural springs on every triangle edge, bending
// springs r-l across every interior edge. Vertex (c, r) has id r * columns + c.
Sheet buildRectangleSheet(const SheetSpec& spec);

} // namespace pf
