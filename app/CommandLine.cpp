#include "CommandLine.h"

#include "Integrator.h"
#include "OutputFile.h"
#include "WorkerPool.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <QTextStream>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <sys/stat.h>
#include <utility>

namespace pf::cli {

std::string integratorOption(const QCommandLineParser& parser) {
    const QString name = parser.value(QStringLiteral("integrator"));
    const auto& names = integratorNames();
    if (std::find(names.begin(), names.end(), name.toStdString()) != names.end())
        return name.toStdString();
    QStringList known;
    for (const auto& n : names) known << QString::fromStdString(n);
    throw UsageError{QStringLiteral("--integrator: unknown integrator '%1' (known: %2)")
                         .arg(name, known.join(QStringLiteral(", ")))};
}

void refuseOptionsTheIntegratorIgnores(const QCommandLineParser& parser,
                                       const std::string& integrator) {
    const bool jacobi = integrator == "jacobi" || integrator == "jacobi-scalar";
    const struct {
        const char* option;
        bool read;
        const char* readBy;
    } options[] = {
        {"substeps", integrator == "xpbd", "xpbd"},
        {"no-self-contact", integrator == "xpbd", "xpbd"},
        {"iterations", jacobi, "jacobi and jacobi-scalar"},
        {"gravity-outside-filter", jacobi, "jacobi and jacobi-scalar"},
    };
    const QStringList given = parser.optionNames();
    for (const auto& o : options)
        if (!o.read && given.contains(QLatin1String(o.option)))
            throw UsageError{QStringLiteral("--%1 applies to %2 only; the integrator here is %3")
                                 .arg(QLatin1String(o.option), QLatin1String(o.readBy),
                                      QString::fromStdString(integrator))};
}

void refuseWithout(const QCommandLineParser& parser, std::initializer_list<const char*> options,
                   const char* needed) {
    if (parser.isSet(QLatin1String(needed))) return;
    for (const char* option : options)
        if (parser.isSet(QLatin1String(option)))
            throw UsageError{QStringLiteral("--%1 applies only with --%2, which is not given")
                                 .arg(QLatin1String(option), QLatin1String(needed))};
}

bool sameOutput(const QString& a, const QString& b) {
    const QFileInfo x(a), y(b);
    if (QDir::cleanPath(x.absoluteFilePath()) == QDir::cleanPath(y.absoluteFilePath())) return true;
    struct stat sx {};
    struct stat sy {};
    return stat(QFile::encodeName(a).constData(), &sx) == 0 &&
           stat(QFile::encodeName(b).constData(), &sy) == 0 && sx.st_dev == sy.st_dev &&
           sx.st_ino == sy.st_ino;
}

int checkOutputWritten(int code) {
    if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
    const int why = errno;
    QTextStream(stderr) << "paperfold: the output could not be written (" << std::strerror(why)
                        << ")\n";
    return code != 0 ? code : 2;
}

void addThreadsOption(QCommandLineParser& parser) {
    parser.addOption({QStringLiteral("threads"),
                      QStringLiteral("Threads the step runs on (default: all cores, %1 here). The "
                                     "result is the same, bit for bit, on any number.")
                          .arg(WorkerPool::machineThreads()),
                      QStringLiteral("n")});
}

int threadsOption(const QCommandLineParser& parser) {
    return static_cast<int>(integerOption(parser, QStringLiteral("threads"), 1, 64)
                                .value_or(WorkerPool::machineThreads()));
}

std::optional<double> realOption(const QCommandLineParser& parser, const QString& name, double min,
                                 double max) {
    if (!parser.isSet(name)) return std::nullopt;
    bool ok = false;
    const QString text = parser.value(name);
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value))
        throw UsageError{QStringLiteral("--%1: '%2' is not a number").arg(name, text)};
    if (value < min || value > max)
        throw UsageError{
            QStringLiteral("--%1: %2 is outside [%3, %4]").arg(name, text).arg(min).arg(max)};
    return value;
}

std::optional<long long> integerOption(const QCommandLineParser& parser, const QString& name,
                                       long long min, long long max) {
    if (!parser.isSet(name)) return std::nullopt;
    bool ok = false;
    const QString text = parser.value(name);
    const long long value = text.toLongLong(&ok);
    if (!ok) throw UsageError{QStringLiteral("--%1: '%2' is not a whole number").arg(name, text)};
    if (value < min || value > max)
        throw UsageError{
            QStringLiteral("--%1: %2 is outside [%3, %4]").arg(name, text).arg(min).arg(max)};
    return value;
}

std::optional<std::uint64_t> seedOption(const QCommandLineParser& parser, const QString& name) {
    if (!parser.isSet(name)) return std::nullopt;
    bool ok = false;
    const QString text = parser.value(name);
    const qulonglong value = text.toULongLong(&ok);
    if (!ok)
        throw UsageError{
            QStringLiteral("--%1: '%2' is not a whole number from 0 to 2^64-1").arg(name, text)};
    return static_cast<std::uint64_t>(value);
}

void requireWritable(const QString& option, const QString& path, const QStringList& inputs) {
    const QString problem = checkOutputPath(path, inputs);
    if (!problem.isEmpty()) throw UsageError{QStringLiteral("--%1: %2").arg(option, problem)};
}

void requireDistinctFrames(const QString& option, const OutputPattern& pattern,
                           std::int64_t count) {
    std::map<std::pair<dev_t, ino_t>, std::int64_t> frameOf;
    for (std::int64_t f = 0; f < count; ++f) {
        struct stat st {};
        if (stat(QFile::encodeName(pattern.path(f)).constData(), &st) != 0) continue; // new
        const auto [at, added] = frameOf.try_emplace({st.st_dev, st.st_ino}, f);
        if (!added)
            throw UsageError{QStringLiteral("--%1: frames %2 and %3 ('%4' and '%5') are the same "
                                            "file (a link): the later would overwrite the "
                                            "earlier. Remove the link or choose another name")
                                 .arg(option)
                                 .arg(at->second)
                                 .arg(f)
                                 .arg(pattern.path(at->second), pattern.path(f))};
    }
}

QDir requireFolder(const QString& option, const QString& path) {
    const QFileInfo info(path);
    if (info.exists() && !info.isDir())
        throw UsageError{QStringLiteral("--%1: '%2' is a file, not a folder").arg(option, path)};
    QDir dir(path);
    if (dir.exists()) return dir;
    // The nearest folder that exists says why a new one cannot be made in it.
    QFileInfo parent(QFileInfo(info.absoluteFilePath()).absolutePath());
    while (!parent.exists() && parent.absoluteFilePath() != parent.absolutePath())
        parent = QFileInfo(parent.absolutePath());
    if (!QDir().mkpath(path)) {
        const QString why =
            !parent.isDir()        ? QStringLiteral("'%1' is not a folder").arg(parent.filePath())
            : !parent.isWritable() ? QStringLiteral("'%1' is not writable").arg(parent.filePath())
                                   : QStringLiteral("the system refused");
        throw UsageError{QStringLiteral("--%1: cannot create '%2': %3").arg(option, path, why)};
    }
    return QDir(path);
}

void requirePngName(const QString& option, const QString& path) {
    if (!path.endsWith(QStringLiteral(".png"), Qt::CaseInsensitive))
        throw UsageError{QStringLiteral("--%1: '%2' does not end in .png (the images are PNG)")
                             .arg(option, path)};
}

void rejectExtraArguments(const QCommandLineParser& parser, int allowed) {
    const QStringList extra = parser.positionalArguments().mid(allowed);
    if (!extra.isEmpty())
        throw UsageError{QStringLiteral("unexpected argument '%1'").arg(extra.first())};
}

bool parseCommand(QCommandLineParser& parser, const QStringList& arguments, int positional) {
    if (!parser.parse(arguments)) throw UsageError{parser.errorText()};
    // Every option takes one value: all but the last one given were dropped without a word
    // ("--scene press --scene drape" ran drape).
    const QStringList given = parser.optionNames();
    for (qsizetype k = 0; k < given.size(); ++k)
        if (given.indexOf(given[k]) != k)
            throw UsageError{QStringLiteral("--%1 is given more than once").arg(given[k])};
    // --help-all too (addHelpOption lists it): it ran the command, which for figures,
    // crumple, stability and bench wrote over their output folders.
    if (parser.isSet(QStringLiteral("help")) || parser.isSet(QStringLiteral("help-all"))) {
        QTextStream(stdout) << parser.helpText();
        return false;
    }
    rejectExtraArguments(parser, positional);
    return true;
}

} // namespace pf::cli
