#include "ReplayCommand.h"

#include "CommandLine.h"
#include "RecordingFile.h"
#include "SheetFile.h"
#include "StatsJson.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QTextStream>

namespace pf::cli {

int runReplay(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Do a session recorded in the editor (File > Save Recording) again, headless and bit for "
        "bit: the final state_hash equals the editor's."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("replay"), QStringLiteral("The subcommand."));
    parser.addPositionalArgument(QStringLiteral("recording"),
                                 QStringLiteral("The .paperrec file to replay."));
    parser.addOptions({
        {QStringLiteral("save"), QStringLiteral("Save the final sheet to a .paper file."),
         QStringLiteral("file")},
        {QStringLiteral("stats"), QStringLiteral("Print statistics as one JSON object.")},
    });
    if (!parseCommand(parser, arguments, 2)) return 0;
    if (parser.positionalArguments().size() != 2)
        throw UsageError{QStringLiteral("replay needs one recording file (a .paperrec)")};
    const QString path = parser.positionalArguments()[1];
    if (parser.isSet(QStringLiteral("save")))
        requireWritable(QStringLiteral("save"), parser.value(QStringLiteral("save")), {path});

    RecordingLoad load = loadRecording(path);
    if (!load.log) throw UsageError{load.error};
    EditSession session(*load.log);
    QElapsedTimer timer;
    timer.start();
    const std::string failure = replay(*load.log, session);
    const double wall = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    const long long steps = session.world().stepCount - load.log->start.stepCount;

    QTextStream err(stderr);
    if (parser.isSet(QStringLiteral("save"))) {
        QString error;
        if (!saveWorld(session.world(), parser.value(QStringLiteral("save")), &error, {path})) {
            err << "paperfold: " << error << '\n';
            return 2;
        }
    }
    QJsonObject stats = statsJson(session.world(), wall, steps);
    stats[QStringLiteral("commands")] = static_cast<qint64>(load.log->commands.size());
    stats[QStringLiteral("complete")] = failure.empty();
    if (parser.isSet(QStringLiteral("stats")))
        QTextStream(stdout) << QJsonDocument(stats).toJson(QJsonDocument::Compact) << '\n';
    else
        QTextStream(stdout) << QStringLiteral(
                                   "%1: %2 commands over %3 steps, %4 breaks, state %5\n")
                                   .arg(path)
                                   .arg(load.log->commands.size())
                                   .arg(steps)
                                   .arg(stats[QStringLiteral("breaks")].toInt())
                                   .arg(stats[QStringLiteral("state_hash")].toString());
    if (!failure.empty()) {
        err << "paperfold: the replay stopped: " << QString::fromStdString(failure) << '\n';
        return 3;
    }
    return 0;
}

} // namespace pf::cli
