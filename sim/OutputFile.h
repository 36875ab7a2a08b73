#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace pf {

// The one way PaperFold writes a file: sheets, PNGs, meshes, CSVs and charts all come
// through here (docs/output-files.md).
//
// A target must be a regular file, or a new name in an existing folder PaperFold may
// write to. Device nodes, FIFOs, sockets, folders and broken or looping symbolic links
// are refused, and so is any input of the same command (same device and inode, or the
// same absolute path), so that a typo cannot destroy what the command reads. A symbolic
// link to a regular file is followed: the file it names is replaced, the link stays.

// Empty when path may be written; otherwise one line saying why not. Commands call it
// for every output before long work starts, so a bad target fails in a second, not after
// the work.
QString checkOutputPath(const QString& path, const QStringList& inputs = {});

// Writes bytes atomically: into a new file in the target's folder, every write and the
// fsync checked, then renamed over the target. On failure the target is as it was, no
// temporary file is left, and *error holds one line with the OS's reason (for example
// "No space left on device").
bool writeOutputFile(const QString& path, const QByteArray& bytes, QString* error,
                     const QStringList& inputs = {});

} // namespace pf
