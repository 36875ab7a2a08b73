#include "PngFile.h"

#include "OutputFile.h"

#include <QBuffer>

namespace pf {

bool writePng(const QImage& image, const QString& path, QString* error, const QStringList& inputs) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (image.isNull() || !image.save(&buffer, "PNG")) {
        if (error) *error = QStringLiteral("cannot encode the image for %1 as PNG").arg(path);
        return false;
    }
    return writeOutputFile(path, bytes, error, inputs);
}

} // namespace pf
