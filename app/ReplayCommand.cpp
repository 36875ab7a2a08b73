#include "ReplayCommand.h"

#include "CommandLine.h"
#include "OffscreenRenderer.h"
#include "OutputPattern.h"
#include "PictureOptions.h"
#include "PngFile.h"
#include "RecordingFile.h"
#include "SheetFile.h"
#include "SheetStats.h"
#include "StatsJson.h"
#include "StepProgress.h"

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
        {QStringLiteral("render"),
         QStringLiteral("Render the session as an image sequence (OSMesa, no display): a pattern "
                        "such as frame_%04d.png. The first frame is the start."),
         QStringLiteral("pattern")},
        {QStringLiteral("every"),
         QStringLiteral("Steps between frames (default 4); the last frame is the session's end."),
         QStringLiteral("k")},
    });
    addPictureOptions(parser);
    addThreadsOption(parser);
    if (!parseCommand(parser, arguments, 2)) return 0;
    if (parser.positionalArguments().size() != 2)
        throw UsageError{QStringLiteral("replay needs one recording file (a .paperrec)")};
    const QString path = parser.positionalArguments()[1];
    if (parser.isSet(QStringLiteral("save")))
        requireWritable(QStringLiteral("save"), parser.value(QStringLiteral("save")), {path});
    // Without frames nothing is drawn: a --camera of "garbage" was taken without a word.
    refuseWithout(parser,
                  {"every", "subdiv", "size", "view", "camera", "overlay", "no-legend",
                   "paper-color", "texture"},
                  "render");
    const PictureSetup picture = pictureFromOptions(parser);
    const int threads = threadsOption(parser);
    const int every =
        static_cast<int>(integerOption(parser, QStringLiteral("every"), 1, 1'000'000).value_or(4));
    std::optional<OutputPattern> frames;
    if (parser.isSet(QStringLiteral("render"))) {
        QString error;
        frames = OutputPattern::parse(parser.value(QStringLiteral("render")), &error);
        if (!frames) throw UsageError{QStringLiteral("--render: ") + error};
        if (!frames->hasField())
            throw UsageError{QStringLiteral("--render needs a pattern such as frame_%04d.png")};
    }

    RecordingLoad load = loadRecording(path);
    if (!load.log) throw UsageError{load.error};
    const EditLog& log = *load.log;
    EditSession session(log);
    session.simulation().setThreads(threads);
    QTextStream err(stderr);

    // Frame f shows the sheet after f·every steps, and a last one the session's end when
    // --every does not divide its steps (a session of 16,805 steps rendered every 2,000
    // ended at step 16,000, before the fold it was recorded for); every target is checked
    // before any work.
    const std::int64_t total = log.endStep - log.start.stepCount;
    const bool endApart = total % every != 0;
    const std::int64_t frameCount = total / every + 1 + (endApart ? 1 : 0);
    StepProgress progress(err, QStringLiteral("replaying"), total);
    std::unique_ptr<OffscreenRenderer> renderer;
    OrbitCamera camera;
    auto writeFrame = [&](std::int64_t f) {
        const SheetSnapshot snap = makeSnapshot(session.simulation());
        QString error;
        RenderOptions options = picture.options;
        options.sigma = session.world().params.sigma;
        if (writePng(renderer->render(snap, camera, options), frames->path(int(f)), &error,
                     QStringList{path} + picture.lookInputs))
            return true;
        progress.end();
        err << "paperfold: " << error << '\n';
        return false;
    };
    if (frames) {
        if (frameCount > 100000)
            throw UsageError{QStringLiteral("--render: %1 frames; use a larger --every (at most "
                                            "100000 frames)")
                                 .arg(frameCount)};
        const QString save = parser.value(QStringLiteral("save"));
        for (std::int64_t f = 0; f < frameCount; ++f) {
            requireWritable(QStringLiteral("render"), frames->path(int(f)),
                            QStringList{path} + picture.lookInputs);
            // The sheet was saved over frame 0 (or a frame over the sheet), and rc 0.
            if (!save.isEmpty() && sameOutput(save, frames->path(int(f))))
                throw UsageError{QStringLiteral("--save: '%1' is also frame %2 of --render; "
                                                "choose another name for one of them")
                                     .arg(save)
                                     .arg(f)};
        }
        requireDistinctFrames(QStringLiteral("render"), *frames, frameCount);
        requirePngName(QStringLiteral("render"), frames->path(0));
        QString error;
        renderer = OffscreenRenderer::create(picture.width, picture.height, &error);
        if (!renderer) {
            err << "paperfold: " << error << '\n';
            return 2;
        }
        // Framed on the start and then held, so the sequence does not jitter.
        camera = frameCamera(makeSnapshot(session.simulation()), parser,
                             double(picture.width) / picture.height);
        if (!writeFrame(0)) return 2;
    }
    bool written = true;
    std::function<bool(const EditSession&)> afterStep;
    if (frames || progress.shown())
        afterStep = [&](const EditSession& s) {
            const std::int64_t done = s.world().stepCount - log.start.stepCount;
            if (frames && done % every == 0) written = writeFrame(done / every);
            progress.at(done);
            return written;
        };
    QElapsedTimer timer;
    timer.start();
    const std::string failure = replay(log, session, afterStep);
    progress.end();
    if (!written) return 2;
    if (frames && endApart && failure.empty() && !writeFrame(frameCount - 1)) return 2;
    const double wall = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    const long long steps = session.world().stepCount - log.start.stepCount;
    if (parser.isSet(QStringLiteral("save"))) {
        QString error;
        if (!saveWorld(session.world(), parser.value(QStringLiteral("save")), &error, {path})) {
            err << "paperfold: " << error << '\n';
            return 2;
        }
    }
    QJsonObject stats = statsJson(session.world(), wall, steps);
    stats[QStringLiteral("commands")] = static_cast<qint64>(log.commands.size());
    stats[QStringLiteral("complete")] = failure.empty();
    stats[QStringLiteral("threads")] = session.simulation().threads();
    // A complete replay that ends elsewhere than the recording says: made by another
    // version of PaperFold (its undo and redo changed, say), it replays as this one does;
    // made by this one, replays are bit for bit, so it is a bug. The file does not say
    // which version made it, so the message names both.
    const QString recorded = log.endState
                                 ? QStringLiteral("%1").arg(*log.endState, 16, 16, QLatin1Char('0'))
                                 : QString();
    const bool elsewhere =
        failure.empty() && log.endState && stateHash(session.world().sheet) != *log.endState;
    if (log.endState) stats[QStringLiteral("recorded_state_hash")] = recorded;
    if (failure.empty() && log.endState) stats[QStringLiteral("matches_recording")] = !elsewhere;
    if (parser.isSet(QStringLiteral("stats")))
        QTextStream(stdout) << QJsonDocument(stats).toJson(QJsonDocument::Compact) << '\n';
    else
        QTextStream(stdout) << QStringLiteral(
                                   "%1: %2 commands over %3 steps, %4 breaks, state %5\n")
                                   .arg(path)
                                   .arg(log.commands.size())
                                   .arg(steps)
                                   .arg(stats[QStringLiteral("breaks")].toInt())
                                   .arg(stats[QStringLiteral("state_hash")].toString());
    if (elsewhere)
        err << "paperfold: warning: the replay ended in state "
            << stats[QStringLiteral("state_hash")].toString() << ", the session it recorded in "
            << recorded
            << ": a recording made by another version of PaperFold replays as this version "
               "does; one made by this version should not (a bug: please report it with the "
               "recording)\n";
    if (!failure.empty()) {
        err << "paperfold: the replay stopped: " << QString::fromStdString(failure) << '\n';
        return 3;
    }
    return 0;
}

} // namespace pf::cli
