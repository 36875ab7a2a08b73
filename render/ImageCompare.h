#pragma once

#include <QImage>

namespace pf {

// A noise-tolerant image comparison for rendering tests and `render --reference`.
// Both images are blurred with a 3×3 box (so one-pixel shifts of an edge and
// rasterisation noise mostly cancel). A pixel "differs" when any channel of the
// blurred images differs by more than `channelTolerance` (0-255). The score is the
// fraction of differing pixels; images of different sizes score 1.
//
// The default tolerance, 6, passes llvmpipe's rounding noise but still sees a
// change of shading such as σ = 0 (faceted) against σ = 1 (smooth) on a coarse
// sheet, which differs on 1.3 % of the pixels of tests/baselines/bumps_coarse_*.
struct ImageDifference {
    double differingFraction = 1.0;
    double meanAbsolute = 255.0; // mean |difference| over all channels, 0-255
    QImage map;                  // differing pixels red over a faded copy of the reference
};

ImageDifference compareImages(const QImage& reference, const QImage& actual,
                              int channelTolerance = 6);

} // namespace pf
