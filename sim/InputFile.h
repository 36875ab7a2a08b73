#pragma once

#include <QByteArray>
#include <QString>
#include <optional>

namespace pf {

// Reads a whole regular file of at most `maxBytes`. A device, FIFO or folder is refused
// before it is opened (a FIFO would wait for a writer forever, /dev/zero never ends), and
// checked again on the open file, so nothing can swap it in between. On failure returns
// nothing and sets *error to one line naming the path and the reason.
std::optional<QByteArray> readInputFile(const QString& path, qint64 maxBytes, QString* error);

} // namespace pf
