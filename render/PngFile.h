#pragma once

#include <QImage>
#include <QString>
#include <QStringList>

namespace pf {

// Encodes the image as PNG and writes it through the checked output path
// (OutputFile.h), so a full disk, a device node or an input of the same command is an
// error with the OS's reason, never a truncated or misplaced file.
bool writePng(const QImage& image, const QString& path, QString* error,
              const QStringList& inputs = {});

} // namespace pf
