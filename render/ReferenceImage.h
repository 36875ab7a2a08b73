#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

namespace pf {

// The largest reference image file `render --reference` reads, and the largest side
// it decodes: a reference is compared with a render, which is never larger.
inline constexpr qint64 kMaxReferenceBytes = 64LL * 1024 * 1024;
inline constexpr int kMaxReferenceSide = 8192;

// Decodes a reference PNG from memory. The header's size is checked before any pixel
// is allocated, so a tiny file declaring a huge image costs nothing. A null image and
// *error on failure.
QImage decodeReferenceImage(const QByteArray& bytes, QString* error);

// Reads a reference PNG: a regular file (never a device, whose read would not end) of
// at most kMaxReferenceBytes, then decodeReferenceImage.
QImage readReferenceImage(const QString& path, QString* error);

} // namespace pf
