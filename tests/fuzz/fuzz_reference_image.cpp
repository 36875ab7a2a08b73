// libFuzzer target for `render --reference`: any bytes must be refused with a message
// or decode to an image of bounded size that compares with a render without crashing.
#include "ImageCompare.h"
#include "ReferenceImage.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray bytes =
        QByteArray::fromRawData(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    QString error;
    const QImage image = pf::decodeReferenceImage(bytes, &error);
    if (image.isNull()) {
        if (error.isEmpty()) std::abort();
        return 0;
    }
    if (image.width() > pf::kMaxReferenceSide || image.height() > pf::kMaxReferenceSide)
        std::abort();
    static const QImage render = [] {
        QImage r(16, 12, QImage::Format_RGBA8888);
        r.fill(Qt::white);
        return r;
    }();
    const pf::ImageDifference other = pf::compareImages(image, render);
    const pf::ImageDifference self = pf::compareImages(image, image);
    if (!(other.differingFraction >= 0.0 && other.differingFraction <= 1.0)) std::abort();
    if (self.differingFraction != 0.0) std::abort();
    return 0;
}
