#include "PaperLook.h"

#include "InputFile.h"
#include "PngDecode.h"

#include <QBuffer>
#include <QColor>
#include <QFileInfo>
#include <QImageReader>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pf {

namespace {

// A 32-bit integer hash (lowbias32): the grain must not depend on a library's random
// generator, so that a render baseline holds on every machine.
std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

float lattice(int ix, int iy, std::uint32_t seed) {
    const std::uint32_t h = hash32(static_cast<std::uint32_t>(ix) * 0x9e3779b1U ^
                                   hash32(static_cast<std::uint32_t>(iy) + seed));
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// Smooth value noise with cells of `cx` × `cy` pixels, in 0..1.
float valueNoise(int px, int py, int cx, int cy, std::uint32_t seed) {
    const int ix = px / cx, iy = py / cy;
    float fx = static_cast<float>(px % cx) / cx, fy = static_cast<float>(py % cy) / cy;
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    const float a = lattice(ix, iy, seed), b = lattice(ix + 1, iy, seed);
    const float c = lattice(ix, iy + 1, seed), d = lattice(ix + 1, iy + 1, seed);
    return (a + (b - a) * fx) + ((c + (d - c) * fx) - (a + (b - a) * fx)) * fy;
}

QImage makeGrain() {
    // 1024² over an A4 sheet is about 0.2-0.3 mm a pixel: the scale of paper's
    // formation. Rows run along the sheet's length (v), the machine direction, so
    // fibres are cells long in y and short in x.
    constexpr int side = 1024;
    QImage image(side, side, QImage::Format_RGBA8888);
    for (int y = 0; y < side; ++y) {
        uchar* row = image.scanLine(y);
        for (int x = 0; x < side; ++x) {
            const float cloud = 0.55f * valueNoise(x, y, 48, 48, 11u) +
                                0.30f * valueNoise(x, y, 16, 16, 23u) +
                                0.15f * valueNoise(x, y, 5, 5, 37u);
            const float fibre = valueNoise(x, y, 2, 14, 53u);
            const float shade = 1.0f - 0.07f * cloud - 0.05f * std::max(0.0f, fibre - 0.6f) / 0.4f;
            // A touch warmer in the darker places, as pulp is.
            const float dark = 1.0f - shade;
            const float r = shade, g = shade - 0.04f * dark, b = shade - 0.12f * dark;
            row[4 * x + 0] = static_cast<uchar>(std::lround(255 * std::clamp(r, 0.0f, 1.0f)));
            row[4 * x + 1] = static_cast<uchar>(std::lround(255 * std::clamp(g, 0.0f, 1.0f)));
            row[4 * x + 2] = static_cast<uchar>(std::lround(255 * std::clamp(b, 0.0f, 1.0f)));
            row[4 * x + 3] = 255;
        }
    }
    return image;
}

} // namespace

QImage paperGrainImage() {
    // Made once: its cacheKey then stays the same, and the renderer uploads it once.
    static const QImage grain = makeGrain();
    return grain;
}

QImage paperTextureImage(const PaperLook& look) {
    switch (look.texture) {
    case PaperTexture::Plain:
        return {};
    case PaperTexture::Grain:
        return paperGrainImage();
    case PaperTexture::Image:
        return look.image;
    }
    return {};
}

bool loadPaperImage(const QString& path, QImage* image, QString* error) {
    // Qt's reader would print "No file name specified" to the console and fail anyway
    // (the editor's first session, with no texture saved, asked for this).
    if (path.isEmpty()) {
        if (error) *error = QStringLiteral("no picture was named for the paper texture");
        return false;
    }
    // A photograph is a few MB; past this the file is not meant for paper.
    constexpr qint64 kMaxTextureFileBytes = qint64(256) << 20;
    // Read as a whole regular file first: a FIFO named as the texture (or a device) kept
    // Qt's reader waiting for a writer forever, and a folder read "File not found".
    const std::optional<QByteArray> bytes = readInputFile(path, kMaxTextureFileBytes, error);
    if (!bytes) return false;
    // Past this a header is lying or the picture is not meant for paper; refusing
    // before decoding keeps a hostile file from taking the memory.
    constexpr int kMaxReadSide = 65536;
    const QString name = QFileInfo(path).fileName();
    const auto fail = [&](const QString& why) {
        if (error) *error = QStringLiteral("%1: %2").arg(name, why);
        return false;
    };
    QImage read;
    if (hasPngSignature(*bytes)) {
        // Not through Qt's reader, whose libpng printed its own line of a damaged PNG.
        QString why;
        read = decodePng(*bytes, kMaxReadSide, &why);
        if (read.isNull()) return fail(why);
    } else {
        QBuffer buffer;
        buffer.setData(*bytes);
        buffer.open(QIODevice::ReadOnly);
        QImageReader reader(&buffer);
        reader.setAutoTransform(true);
        const QSize size = reader.size();
        if (size.isValid() && (size.width() > kMaxReadSide || size.height() > kMaxReadSide))
            return fail(QStringLiteral("%1 x %2 pixels, too large for a paper texture")
                            .arg(size.width())
                            .arg(size.height()));
        // Scaling while decoding keeps a huge photo from taking its full size in memory
        // (where the format can: JPEG).
        if (size.isValid() && std::max(size.width(), size.height()) > kMaxTextureSide)
            reader.setScaledSize(
                size.scaled(kMaxTextureSide, kMaxTextureSide, Qt::KeepAspectRatio));
        read = reader.read();
        if (read.isNull()) return fail(reader.errorString());
    }
    if (std::max(read.width(), read.height()) > kMaxTextureSide)
        read = read.scaled(kMaxTextureSide, kMaxTextureSide, Qt::KeepAspectRatio,
                           Qt::SmoothTransformation);
    *image = read.convertToFormat(QImage::Format_RGBA8888);
    return true;
}

std::optional<std::array<float, 3>> paperColorFromText(const QString& text, QString* error) {
    const QColor c = QColor::fromString(text.trimmed());
    if (!c.isValid()) {
        if (error)
            *error = QStringLiteral("'%1' is not a colour: use #rrggbb or a name such as ivory")
                         .arg(text);
        return std::nullopt;
    }
    // Paper is opaque: "transparent" (QColor's name for black with no alpha) and
    // #aarrggbb were taken, their alpha dropped, as black or another colour.
    if (c.alpha() != 255) {
        if (error)
            *error = QStringLiteral("'%1' is not opaque: paper is; use #rrggbb or a name such as "
                                    "ivory")
                         .arg(text);
        return std::nullopt;
    }
    return std::array<float, 3>{static_cast<float>(c.redF()), static_cast<float>(c.greenF()),
                                static_cast<float>(c.blueF())};
}

QString paperColorText(const std::array<float, 3>& color) {
    return QColor::fromRgbF(color[0], color[1], color[2]).name(QColor::HexRgb);
}

bool setPaperTextureFromText(const QString& text, PaperLook* look, QString* error) {
    if (text == QLatin1String("plain")) {
        look->texture = PaperTexture::Plain;
        look->image = {};
        return true;
    }
    if (text == QLatin1String("grain")) {
        look->texture = PaperTexture::Grain;
        look->image = {};
        return true;
    }
    QImage image;
    if (!loadPaperImage(text, &image, error)) return false;
    look->texture = PaperTexture::Image;
    look->image = image;
    look->imagePath = text;
    return true;
}

QString paperTextureText(const PaperLook& look) {
    switch (look.texture) {
    case PaperTexture::Plain:
        break;
    case PaperTexture::Grain:
        return QStringLiteral("grain");
    case PaperTexture::Image:
        return look.imagePath;
    }
    return QStringLiteral("plain");
}

SurfaceLook surfaceLook(const PaperLook& look) {
    SurfaceLook out;
    out.color = look.color;
    const QImage texture = paperTextureImage(look);
    if (!texture.isNull()) {
        QBuffer buffer(&out.texturePng);
        buffer.open(QIODevice::WriteOnly);
        texture.save(&buffer, "PNG");
    }
    return out;
}

} // namespace pf
