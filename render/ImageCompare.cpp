#include "ImageCompare.h"

#include <cstdlib>
#include <vector>

namespace pf {

namespace {

// 3×3 box blur of one 8-bit RGB image into int channels (edges clamped).
std::vector<int> blurred(const QImage& img) {
    const int w = img.width(), h = img.height();
    std::vector<int> out(static_cast<std::size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int sum[3] = {0, 0, 0};
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const QRgb p =
                        img.pixel(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1));
                    sum[0] += qRed(p);
                    sum[1] += qGreen(p);
                    sum[2] += qBlue(p);
                }
            for (int c = 0; c < 3; ++c)
                out[(static_cast<std::size_t>(y) * w + x) * 3 + c] = sum[c] / 9;
        }
    return out;
}

} // namespace

ImageDifference compareImages(const QImage& reference, const QImage& actual, int channelTolerance) {
    ImageDifference d;
    if (reference.size() != actual.size() || reference.isNull()) return d;
    const QImage a = reference.convertToFormat(QImage::Format_RGB32);
    const QImage b = actual.convertToFormat(QImage::Format_RGB32);
    const std::vector<int> ba = blurred(a), bb = blurred(b);
    const int w = a.width(), h = a.height();
    d.map = QImage(w, h, QImage::Format_RGB32);
    long differing = 0;
    double total = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 3;
            int worst = 0;
            for (int c = 0; c < 3; ++c) {
                const int diff = std::abs(ba[i + c] - bb[i + c]);
                worst = std::max(worst, diff);
                total += diff;
            }
            const bool differs = worst > channelTolerance;
            differing += differs;
            const int grey = qGray(a.pixel(x, y)) / 3 + 170;
            d.map.setPixel(x, y, differs ? qRgb(230, 20, 20) : qRgb(grey, grey, grey));
        }
    d.differingFraction = static_cast<double>(differing) / (static_cast<double>(w) * h);
    d.meanAbsolute = total / (3.0 * w * h);
    return d;
}

} // namespace pf
