#include "PngDecode.h"

#include <png.h>

namespace pf {

bool hasPngSignature(const QByteArray& bytes) {
    return bytes.startsWith(QByteArrayView("\x89PNG\r\n\x1a\n", 8));
}

QImage decodePng(const QByteArray& bytes, int maxSide, QString* error) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    const auto fail = [&](const QString& why) {
        png_image_free(&png);
        if (error) *error = why;
        return QImage();
    };
    // libpng's own words for what is wrong ("IDAT: invalid code lengths set").
    const auto damaged = [&] {
        return fail(QStringLiteral("a damaged PNG (%1)").arg(QString::fromUtf8(png.message)));
    };
    if (!png_image_begin_read_from_memory(&png, bytes.constData(), std::size_t(bytes.size())))
        return damaged();
    if (png.width > png_uint_32(maxSide) || png.height > png_uint_32(maxSide))
        return fail(QStringLiteral("a %1x%2 image is larger than %3 pixels a side")
                        .arg(png.width)
                        .arg(png.height)
                        .arg(maxSide));
    // Qt's reader refused a picture of more than 256 MiB (its allocation limit); the
    // same here, or a 60000-pixel square of a few kB would take 14 GB.
    constexpr quint64 kMaxBytes = quint64(256) << 20;
    if (quint64(png.width) * png.height * 4 > kMaxBytes)
        return fail(
            QStringLiteral("a %1x%2 image needs more than 256 MiB").arg(png.width).arg(png.height));
    png.format = PNG_FORMAT_RGBA;
    QImage image(int(png.width), int(png.height), QImage::Format_RGBA8888);
    if (image.isNull())
        return fail(QStringLiteral("no memory for a %1x%2 image").arg(png.width).arg(png.height));
    if (!png_image_finish_read(&png, nullptr, image.bits(), png_int_32(image.bytesPerLine()),
                               nullptr))
        return damaged();
    return image;
}

} // namespace pf
