#include "HeatColor.h"

#include <algorithm>
#include <cmath>

namespace pf {

std::array<float, 3> heatColor(double t) {
    static constexpr float stops[5][3] = {{0.10f, 0.15f, 0.55f},
                                          {0.05f, 0.70f, 0.85f},
                                          {0.98f, 0.90f, 0.20f},
                                          {0.98f, 0.55f, 0.10f},
                                          {0.80f, 0.05f, 0.05f}};
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
    const int i = std::min(static_cast<int>(t), 3);
    const float u = static_cast<float>(t - i);
    std::array<float, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = stops[i][k] + u * (stops[i + 1][k] - stops[i][k]);
    return c;
}

} // namespace pf
