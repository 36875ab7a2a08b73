#include "DisplayCheck.h"

#include <QByteArray>
#include <QRegularExpression>
#include <cstring>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

namespace pf {

namespace {

// Connects to an X server's local socket: the file /tmp/.X11-unix/XN or its name in
// the abstract namespace (what Xvfb and Xorg both listen on).
bool localXServerAnswers(int display) {
    const QByteArray path = "/tmp/.X11-unix/X" + QByteArray::number(display);
    for (bool abstract : {false, true}) {
        const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (fd < 0) return true; // cannot tell; let Qt try
        sockaddr_un addr{};
        addr.sun_family = AF_UNIX;
        const std::size_t offset = abstract ? 1 : 0;
        std::memcpy(addr.sun_path + offset, path.constData(), std::size_t(path.size()));
        const socklen_t length =
            socklen_t(offsetof(sockaddr_un, sun_path) + offset + std::size_t(path.size()));
        const bool connected = ::connect(fd, reinterpret_cast<sockaddr*>(&addr), length) == 0;
        ::close(fd);
        if (connected) return true;
    }
    return false;
}

} // namespace

QString displayProblem() {
    const QByteArray platform = qgetenv("QT_QPA_PLATFORM");
    if (!platform.isEmpty() && !platform.startsWith("xcb")) return {}; // Qt was told where
    const QByteArray wayland = qgetenv("WAYLAND_DISPLAY");
    const QByteArray x = qgetenv("DISPLAY");
    if (platform.isEmpty() && !wayland.isEmpty()) return {};
    if (x.isEmpty())
        return QStringLiteral("the editor needs a display, and none is set (DISPLAY is empty)");
    // Only local displays (":0", ":1.0", "unix:2") can be checked without X libraries.
    static const QRegularExpression local(QStringLiteral("^(unix)?:(\\d+)(\\.\\d+)?$"));
    const QRegularExpressionMatch m = local.match(QString::fromLocal8Bit(x));
    if (m.hasMatch() && !localXServerAnswers(m.captured(2).toInt()))
        return QStringLiteral("the editor cannot reach the display %1")
            .arg(QString::fromLocal8Bit(x));
    return {};
}

} // namespace pf
