#include "SimulateCommand.h"

#include "CommandLine.h"
#include "SheetFile.h"
#include "Simulation.h"
#include "StatsJson.h"
#include "StepProgress.h"
#include "WorldOptions.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QTextStream>

namespace pf::cli {

int runSimulate(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Run a scene or a saved sheet headless and report statistics."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("simulate"), QStringLiteral("The subcommand."));
    addWorldOptions(parser);
    addThreadsOption(parser);
    parser.addOptions({
        {QStringLiteral("steps"), QStringLiteral("Number of steps (default 600)."),
         QStringLiteral("n")},
        {QStringLiteral("save"), QStringLiteral("Save the sheet to a .paper file afterwards."),
         QStringLiteral("file")},
        {QStringLiteral("stats"), QStringLiteral("Print statistics as one JSON object.")},
    });
    if (!parseCommand(parser, arguments)) return 0;
    const QStringList inputs = worldInputs(parser);
    if (parser.isSet(QStringLiteral("save")))
        requireWritable(QStringLiteral("save"), parser.value(QStringLiteral("save")), inputs);
    const long long steps =
        integerOption(parser, QStringLiteral("steps"), 0, 1'000'000'000).value_or(600);
    const int threads = threadsOption(parser);
    World world = worldFromOptions(parser);

    Simulation sim(std::move(world));
    sim.setThreads(threads);
    QTextStream err(stderr);
    StepProgress progress(err, QStringLiteral("simulating"), steps);
    QElapsedTimer timer;
    timer.start();
    long long done = 0;
    bool diverged = false;
    for (; done < steps; ++done) {
        if (sim.step() != StepStatus::Ok) {
            diverged = true;
            break;
        }
        progress.at(done + 1);
    }
    const double wall = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    progress.end();

    if (parser.isSet(QStringLiteral("save"))) {
        QString error;
        if (!saveWorld(sim.world(), parser.value(QStringLiteral("save")), &error, inputs)) {
            err << "paperfold: " << error << '\n';
            return 2;
        }
    }
    QJsonObject stats = statsJson(sim.world(), wall, done);
    stats[QStringLiteral("diverged")] = diverged;
    stats[QStringLiteral("threads")] = sim.threads();
    // A saved sheet is named by its file; "scene" stays the scene it began as.
    QString name = stats[QStringLiteral("scene")].toString();
    if (parser.isSet(QStringLiteral("load"))) {
        const QString file = parser.value(QStringLiteral("load"));
        stats[QStringLiteral("loaded")] = file;
        name = QStringLiteral("%1 (begun as %2)").arg(QFileInfo(file).fileName(), name);
    }
    if (parser.isSet(QStringLiteral("stats"))) {
        QTextStream(stdout) << QJsonDocument(stats).toJson(QJsonDocument::Compact) << '\n';
    } else {
        QTextStream(stdout) << QStringLiteral("%1: %2 steps, %3 breaks, %4 hinges, %5 steps/s\n")
                                   .arg(name)
                                   .arg(done)
                                   .arg(stats[QStringLiteral("breaks")].toInt())
                                   .arg(stats[QStringLiteral("hinges")].toInt())
                                   .arg(stats[QStringLiteral("steps_per_second")].toDouble(), 0,
                                        'f', 0);
    }
    if (diverged) {
        err << QStringLiteral("paperfold: the simulation diverged at step %1 (non-finite or "
                              "exploding state); the last good state was kept; try a smaller "
                              "--dt or an implicit integrator\n")
                   .arg(done + 1);
        return 3;
    }
    return 0;
}

} // namespace pf::cli
