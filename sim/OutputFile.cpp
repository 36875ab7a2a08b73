#include "OutputFile.h"

#include "UnfinishedOutputs.h"

#include <QFile>
#include <QFileInfo>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <optional>
#include <random>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace pf {

namespace {

QString osReason(int err) {
    return QString::fromStdString(std::error_code(err, std::generic_category()).message());
}

QString folderOf(const QByteArray& path) {
    const QString p = QFile::decodeName(path);
    const QString dir = QFileInfo(p).path();
    return dir.isEmpty() ? QStringLiteral(".") : dir;
}

// Where the bytes for `path` go (a link's target) and whether a file is there now.
struct Target {
    QByteArray path;
    bool exists = false;
    mode_t mode = 0;
};

bool sameFile(const struct stat& a, const struct stat& b) {
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// Empty on success; fills *target.
QString resolveTarget(const QString& path, const QStringList& inputs, Target* target) {
    if (path.isEmpty()) return QStringLiteral("no output file name was given");
    const QByteArray name = QFile::encodeName(path);
    target->path = name;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    for (const QString& input : inputs)
        if (!input.isEmpty() && QFileInfo(input).absoluteFilePath() == absolute)
            return QStringLiteral("'%1' is also an input of this command; writing it would "
                                  "destroy it (choose another name)")
                .arg(path);

    struct stat st {};
    if (lstat(name.constData(), &st) != 0) {
        if (errno != ENOENT)
            return QStringLiteral("cannot write '%1': %2").arg(path, osReason(errno));
    } else {
        if (S_ISLNK(st.st_mode)) {
            if (stat(name.constData(), &st) != 0) {
                if (errno == ELOOP)
                    return QStringLiteral("'%1' is a loop of symbolic links").arg(path);
                if (errno == ENOENT)
                    return QStringLiteral("'%1' is a symbolic link to nothing").arg(path);
                return QStringLiteral("cannot write '%1': %2").arg(path, osReason(errno));
            }
            char* real = realpath(name.constData(), nullptr);
            if (!real) return QStringLiteral("cannot write '%1': %2").arg(path, osReason(errno));
            target->path = QByteArray(real);
            std::free(real);
        }
        if (S_ISDIR(st.st_mode)) return QStringLiteral("'%1' is a folder, not a file").arg(path);
        if (!S_ISREG(st.st_mode))
            return QStringLiteral("'%1' is not a regular file (a device, FIFO or socket); "
                                  "PaperFold writes only regular files")
                .arg(path);
        for (const QString& input : inputs) {
            struct stat in {};
            if (!input.isEmpty() && stat(QFile::encodeName(input).constData(), &in) == 0 &&
                sameFile(in, st))
                return QStringLiteral("'%1' is the same file as the input '%2'; writing it "
                                      "would destroy it (choose another name)")
                    .arg(path, input);
        }
        target->exists = true;
        target->mode = st.st_mode & 07777;
    }

    const QString folder = folderOf(target->path);
    const QByteArray folderName = QFile::encodeName(folder);
    struct stat dir {};
    if (stat(folderName.constData(), &dir) != 0)
        return errno == ENOENT
                   ? QStringLiteral("the folder '%1' does not exist").arg(folder)
                   : QStringLiteral("cannot use the folder '%1': %2").arg(folder, osReason(errno));
    if (!S_ISDIR(dir.st_mode)) return QStringLiteral("'%1' is not a folder").arg(folder);
    // Root passes the permission bits, but a read-only file system still says EROFS here.
    if (access(folderName.constData(), W_OK | X_OK) != 0)
        return QStringLiteral("cannot write in the folder '%1': %2").arg(folder, osReason(errno));
    return {};
}

// A name for the temporary file that no other writer (thread or process) picks.
QByteArray temporaryName(const QByteArray& target, int attempt) {
    static std::atomic<unsigned> counter{0};
    thread_local std::mt19937_64 random{std::random_device{}()};
    const QByteArray folder = QFile::encodeName(folderOf(target));
    const QByteArray base = QFile::encodeName(QFileInfo(QFile::decodeName(target)).fileName());
    return folder + "/." + base.left(64) + '.' + QByteArray::number(getpid()) + '.' +
           QByteArray::number(counter++) + '.' + QByteArray::number(random() % 1000000) + '.' +
           QByteArray::number(attempt) + ".tmp";
}

bool writeAll(int fd, const QByteArray& bytes, int* err) {
    const char* p = bytes.constData();
    qsizetype left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, static_cast<size_t>(std::min<qsizetype>(left, 1 << 24)));
        if (n < 0) {
            if (errno == EINTR) continue;
            *err = errno;
            return false;
        }
        p += n;
        left -= n;
    }
    return true;
}

} // namespace

QString checkOutputPath(const QString& path, const QStringList& inputs) {
    Target target;
    if (QString problem = resolveTarget(path, inputs, &target); !problem.isEmpty()) return problem;
    // The permission bits do not say everything: root passes them in /proc and /sys, whose
    // file systems then refuse a new file, and a save there failed only after the whole
    // run. So a file is made in the folder, as the write will make its temporary one, and
    // removed at once.
    for (int attempt = 0; attempt < 16; ++attempt) {
        const QByteArray probe = temporaryName(target.path, attempt);
        const UnfinishedOutput unfinished(probe); // a Ctrl+C meanwhile removes it
        const int fd = ::open(probe.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd >= 0) {
            ::close(fd);
            ::unlink(probe.constData());
            return {};
        }
        if (errno != EEXIST)
            return QStringLiteral("cannot write '%1': %2").arg(path, osReason(errno));
    }
    return {}; // every name taken: the write itself will say so
}

bool writeOutputFile(const QString& path, const QByteArray& bytes, QString* error,
                     const QStringList& inputs) {
    auto failWith = [&](const QString& message) {
        if (error) *error = message;
        return false;
    };
    Target target;
    if (const QString problem = resolveTarget(path, inputs, &target); !problem.isEmpty())
        return failWith(problem);

    QByteArray temp;
    int fd = -1;
    // A Ctrl+C removes the temporary file. Named before it is made, so that there is no
    // moment when it exists unnamed (a kill the moment it appeared left it, once in CI).
    std::optional<UnfinishedOutput> unfinished;
    for (int attempt = 0; fd < 0 && attempt < 16; ++attempt) {
        temp = temporaryName(target.path, attempt);
        unfinished.emplace(temp);
        // 0666 less the umask, like any new file; an existing file keeps its mode below.
        fd = ::open(temp.constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0) {
            const int why = errno;
            unfinished.reset(); // not ours: another writer's, or none
            if (why != EEXIST)
                return failWith(QStringLiteral("cannot write '%1': %2").arg(path, osReason(why)));
        }
    }
    if (fd < 0)
        return failWith(QStringLiteral("cannot write '%1': no free temporary name").arg(path));

    int err = 0;
    bool ok = writeAll(fd, bytes, &err);
    if (ok && target.exists && fchmod(fd, target.mode) != 0) ok = (err = errno, false);
    // Without the fsync a crash after the rename could leave an empty file under the name.
    if (ok && fsync(fd) != 0) ok = (err = errno, false);
    if (::close(fd) != 0 && ok) ok = (err = errno, false);
    if (ok && ::rename(temp.constData(), target.path.constData()) != 0) ok = (err = errno, false);
    if (!ok) {
        ::unlink(temp.constData());
        return failWith(QStringLiteral("cannot write '%1': %2").arg(path, osReason(err)));
    }
    const int dirFd = ::open(QFile::encodeName(folderOf(target.path)).constData(),
                             O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirFd >= 0) {
        fsync(dirFd); // the rename itself is durable once the folder is synced
        ::close(dirFd);
    }
    return true;
}

} // namespace pf
