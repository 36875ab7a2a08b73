#include "InputFile.h"

#include <QFile>
#include <algorithm>
#include <cerrno>
#include <sys/stat.h>
#include <system_error>

namespace pf {

std::optional<QByteArray> readInputFile(const QString& path, qint64 maxBytes, QString* error) {
    // (QFile warns on stderr, in its own words, before it fails on an empty name.)
    if (path.isEmpty()) {
        *error = QStringLiteral("no file named (the name is empty)");
        return std::nullopt;
    }
    const QString notRegular =
        QStringLiteral("%1 is not a regular file (a device, FIFO or folder)");
    struct stat before {};
    if (stat(QFile::encodeName(path).constData(), &before) == 0 && !S_ISREG(before.st_mode)) {
        *error = notRegular.arg(path);
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot open %1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    struct stat st {};
    if (fstat(file.handle(), &st) != 0) {
        *error = QStringLiteral("cannot open %1: %2")
                     .arg(path, QString::fromStdString(
                                    std::error_code(errno, std::generic_category()).message()));
        return std::nullopt;
    }
    if (!S_ISREG(st.st_mode)) {
        *error = notRegular.arg(path);
        return std::nullopt;
    }
    if (st.st_size > maxBytes) {
        *error = QStringLiteral("%1 is larger than %2 MiB").arg(path).arg(maxBytes >> 20);
        return std::nullopt;
    }
    // Asked for exactly what is there (plus one byte to see a file that grew): QIODevice
    // reserves the size it is asked for.
    return file.read(std::min<qint64>(st.st_size, maxBytes) + 1);
}

} // namespace pf
