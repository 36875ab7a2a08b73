#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

namespace pf {

// Whether the bytes begin with the PNG signature.
bool hasPngSignature(const QByteArray& bytes);

// Decodes a PNG held in memory to RGBA, 8 bits a channel, through libpng's simplified
// API, which hands its errors back as text. Qt's reader let libpng print "libpng error:
// IDAT: invalid code lengths set" on the console before our own line said the file could
// not be read. The header is read first: an image wider or taller than `maxSide` is
// refused before any pixel is allocated, as is one of more than 256 MiB. A null image
// and *error on failure.
QImage decodePng(const QByteArray& bytes, int maxSide, QString* error);

} // namespace pf
