#pragma once

#include "World.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace pf {

// The .paper file: a CBOR map holding a whole World (docs/sheet-file.md lists every
// field). Saving then loading gives back a World that steps bit for bit like the original.
inline constexpr int kSheetFileVersion = 1;
inline constexpr const char* kSheetFileMagic = "PaperFold sheet";

// Files larger than this are refused before they are read.
inline constexpr qint64 kMaxSheetFileBytes = 512LL * 1024 * 1024;
// Element counts beyond these are refused before anything is allocated.
inline constexpr qint64 kMaxFileVertices = 4'000'000;
inline constexpr qint64 kMaxFileSprings = 32'000'000;
inline constexpr qint64 kMaxFileTriangles = 16'000'000;
inline constexpr qint64 kMaxFileEvents = 8'000'000;

QByteArray encodeWorld(const World& world);

// The parameters alone, in the file's "params" encoding (a recording stores changes so).
QByteArray encodeParams(const SimParams& params);
// Checked as the sheet loader checks them; nothing and *error set if they are not valid.
std::optional<SimParams> decodeParams(const QByteArray& bytes, QString* error);

struct WorldLoad {
    std::optional<World> world;
    QString error; // one line naming what is wrong, when world is empty
};

// Decodes and validates everything; never trusts a count or an index it was given.
WorldLoad decodeWorld(const QByteArray& bytes);

// Through the checked output path (OutputFile.h): atomic, refuses devices and any of
// `inputs`, reports the OS's reason. A crash or a full disk leaves the previous file intact.
bool saveWorld(const World& world, const QString& path, QString* error,
               const QStringList& inputs = {});
// Refuses anything but a regular file before reading it; memory stays within a small
// multiple of the file's size, whatever keys it holds.
WorldLoad loadWorld(const QString& path);

} // namespace pf
