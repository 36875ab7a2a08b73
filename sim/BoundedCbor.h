#pragma once

#include <QByteArray>
#include <QCborValue>
#include <QSet>
#include <QString>
#include <optional>

namespace pf {

// What a reader is willing to build from a CBOR document.
struct CborBounds {
    // Map entries under any other key (or a key that is not short text) are skipped
    // while streaming, never built.
    QSet<QString> knownKeys;
    int maxDepth = 8;         // containers and tags nested deeper are refused
    qint64 maxValues = 50000; // values built in all (byte and text strings count once)
};

// Parses `bytes` like QCborValue::fromCbor, but builds only what `bounds` keeps, so the
// memory it takes is the kept strings plus a bounded number of values, whatever the
// input holds (QCborValue::fromCbor builds every value, and 50 M tiny arrays under a
// key nobody reads cost gigabytes). Returns nothing and sets *error on malformed or
// out-of-bounds input.
std::optional<QCborValue> parseBoundedCbor(const QByteArray& bytes, const CborBounds& bounds,
                                           QString* error);

} // namespace pf
