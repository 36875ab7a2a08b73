#include "ReferenceImage.h"

#include "PngDecode.h"

#include <QFile>
#include <sys/stat.h>

namespace pf {

QImage decodeReferenceImage(const QByteArray& bytes, QString* error) {
    // A render is a PNG: anything else (a GIF's header once declared one size and decoded
    // to another under the fuzzer) is refused before a decoder sees it.
    if (!hasPngSignature(bytes)) {
        if (error) *error = QStringLiteral("not a PNG image");
        return QImage();
    }
    return decodePng(bytes, kMaxReferenceSide, error);
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
