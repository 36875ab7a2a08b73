#pragma once

#include "OutputPattern.h"

#include <QCommandLineParser>
#include <QDir>
#include <QString>
#include <QStringList>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

namespace pf::cli {

// Thrown for bad command-line input; main() prints the message on one line and exits 1.
struct UsageError {
    QString message;
};

// Reads an option's value if given, checking the type and the inclusive range.
std::optional<double> realOption(const QCommandLineParser& parser, const QString& name, double min,
                                 double max);
std::optional<long long> integerOption(const QCommandLineParser& parser, const QString& name,
                                       long long min, long long max);
std::optional<std::uint64_t> seedOption(const QCommandLineParser& parser, const QString& name);

// The integrator --integrator names; throws UsageError, with the known ones, for any
// other name.
std::string integratorOption(const QCommandLineParser& parser);

// Refuses an option given on the command line that `integrator` does not read
// (--substeps to jacobi, --iterations to xpbd, …): run silently without it, the
// command would report a result the user did not ask for.
void refuseOptionsTheIntegratorIgnores(const QCommandLineParser& parser,
                                       const std::string& integrator);

// Refuses any of `options` given without `needed` (--every without --frames, say): it
// did nothing, and the command said nothing of it.
void refuseWithout(const QCommandLineParser& parser, std::initializer_list<const char*> options,
                   const char* needed);

// Whether two outputs of one command name the same file (the same path once made
// absolute and clean, or the same file on disk): the second written would replace the
// first.
bool sameOutput(const QString& a, const QString& b);

// What a command printed on standard output (statistics, a table, the help) is its
// result: lost to a full disk or a closed output, the command has failed. Flushes it;
// if that failed, says so on standard error and returns `code`, or 2 if `code` is 0.
int checkOutputWritten(int code);

// --threads: the threads a step runs on. addThreadsOption adds it to a command;
// threadsOption reads it (1-64), or gives all the machine's threads when it is not given.
void addThreadsOption(QCommandLineParser& parser);
int threadsOption(const QCommandLineParser& parser);

// Throws UsageError, naming the option, unless `path` may be written (OutputFile.h:
// a regular file or a new name in a writable folder, none of `inputs`). Commands call it
// before long work starts.
void requireWritable(const QString& option, const QString& path, const QStringList& inputs = {});

// Throws UsageError, naming the option, if two of the first `count` frames of `pattern`
// are one file already (a link to another frame, or a hard link): writing the later
// frame would overwrite the earlier one, which then would be lost.
void requireDistinctFrames(const QString& option, const OutputPattern& pattern, std::int64_t count);

// The folder `path`, made if it does not exist; throws UsageError naming `option` and
// why it cannot be (a file of that name is there, or what stopped the making of it).
QDir requireFolder(const QString& option, const QString& path);

// Throws UsageError, naming the option, unless `path` ends in .png: what the commands
// that render write is PNG, and a file named otherwise would not open as what it says.
void requirePngName(const QString& option, const QString& path);

// Throws UsageError for positional arguments beyond the subcommand itself.
void rejectExtraArguments(const QCommandLineParser& parser, int allowed);

// Parses a subcommand's arguments: throws UsageError for unknown options or extra
// arguments; prints the help and returns false for --help.
// `positional` counts the subcommand itself.
bool parseCommand(QCommandLineParser& parser, const QStringList& arguments, int positional = 1);

} // namespace pf::cli
