#pragma once

#include <array>

namespace pf {

// The heat-map colour of t in [0, 1] (clamped): dark blue, cyan, yellow, orange, red.
// Used for the surface, the edge overlays and the legend, so all three agree.
std::array<float, 3> heatColor(double t);

} // namespace pf
