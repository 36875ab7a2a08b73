#include "ReferenceImage.h"

#include <QBuffer>
#include <QFile>
#include <QImageReader>
#include <sys/stat.h>

namespace pf {

QImage decodeReferenceImage(const QByteArray& bytes, QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = why;
        return QImage();
    };
    // Qt hands a PNG to libpng, whose own handler prints "libpng error: Not a PNG file" on
    // the console before our line says it again: its signature is checked here first.
    if (!bytes.startsWith(QByteArrayView("\x89PNG\r\n\x1a\n", 8)))
        return fail(QStringLiteral("not a PNG image"));
    QBuffer buffer;
    buffer.setData(bytes);
    buffer.open(QIODevice::ReadOnly);
    QImageReader reader(&buffer, "png");
    // PNG only: with detection on, Qt falls back to other formats (a GIF's header
    // declared one size and decoded to another under the fuzzer).
    reader.setDecideFormatFromContent(false);
    reader.setAutoDetectImageFormat(false);
    const QSize size = reader.size();
    if (!size.isValid()) return fail(QStringLiteral("not a PNG image"));
    if (size.width() > kMaxReferenceSide || size.height() > kMaxReferenceSide)
        return fail(QStringLiteral("a %1x%2 image is larger than any render (%3 pixels a side)")
                        .arg(size.width())
                        .arg(size.height())
                        .arg(kMaxReferenceSide));
    QImage image = reader.read();
    if (image.isNull())
        return fail(QStringLiteral("not a readable PNG: %1").arg(reader.errorString()));
    if (image.size() != size)
        return fail(QStringLiteral("the PNG's size does not match its header"));
    return image;
}

QImage readReferenceImage(const QString& path, QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = QStringLiteral("cannot read the reference image %1: %2").arg(path, why);
        return QImage();
    };
    struct stat st {};
    if (stat(QFile::encodeName(path).constData(), &st) != 0)
        return fail(QStringLiteral("no such file"));
    if (!S_ISREG(st.st_mode)) return fail(QStringLiteral("not a regular file"));
    if (st.st_size > kMaxReferenceBytes)
        return fail(QStringLiteral("larger than %1 MiB").arg(kMaxReferenceBytes >> 20));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return fail(file.errorString());
    QString why;
    const QImage image = decodeReferenceImage(file.read(kMaxReferenceBytes), &why);
    return image.isNull() ? fail(why) : image;
}

} // namespace pf
