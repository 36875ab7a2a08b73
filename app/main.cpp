#include "BenchCommand.h"
#include "CommandLine.h"
#include "CrumpleCommand.h"
#include "EditorMain.h"
#include "ExportCommand.h"
#include "FidelityCommand.h"
#include "FiguresCommand.h"
#include "RenderCommand.h"
#include "ReplayCommand.h"
#include "SimulateCommand.h"
#include "StabilityCommand.h"
#include "UnfinishedOutputs.h"

#include <QApplication>
#include <QByteArrayView>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QLocale>
#include <QTextStream>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <memory>
#include <new>
#include <optional>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>

namespace {

void printUsage(QTextStream& out) {
    out << "usage: paperfold [--lang CODE] [sheet.paper]   start the editor\n"
           "       paperfold <command> [options]           run headless\n"
           "\n"
           "commands:\n"
           "  simulate   run a scene or a saved sheet headless; report statistics, save\n"
           "  export     write the subdivided surface as .obj, .ply or .glb\n"
           "  render     render PNG stills or image sequences with no display (OSMesa)\n"
           "  replay     do a session recorded in the editor again, bit for bit; render it\n"
           "  stability  map where each integrator fails (CSV and heat maps)\n"
           "  fidelity   check the sheet against physics (stretch, free fall, cantilever...)\n"
           "  figures    the paper's Fig. 10-12 as contact sheets with the counts (PNG, CSV)\n"
           "  crumple    crumple and flatten a sheet 10 times: crease length per cycle (CSV, PNG)\n"
           "  bench      speed against accuracy of every integrator configuration (CSV, chart)\n"
           "\n"
           "paperfold <command> --help lists a command's options. The editor needs a\n"
           "display; every command above runs without one.\n";
}

} // namespace

namespace {

// Every command, by the word that names it: the dispatch and the check for a command
// misplaced after the editor's options read the same list.
struct Command {
    std::string_view name;
    int (*run)(const QStringList& arguments);
};
constexpr Command kCommands[] = {
    {"simulate", pf::cli::runSimulate},   {"export", pf::cli::runExport},
    {"render", pf::cli::runRender},       {"replay", pf::cli::runReplay},
    {"stability", pf::cli::runStability}, {"bench", pf::cli::runBench},
    {"fidelity", pf::cli::runFidelity},   {"figures", pf::cli::runFigures},
    {"crumple", pf::cli::runCrumple},
};

const Command* commandNamed(std::string_view word) {
    for (const Command& c : kCommands)
        if (word == c.name) return &c;
    return nullptr;
}

// The editor takes options (--lang, --help-all, ...) and a .paper file; any other first
// word must be a command, so a typo gets an error instead of an editor window.
bool startsEditor(int argc, char* argv[]) {
    if (argc < 2) return true;
    const std::string_view first = argv[1];
    if (first == "--help" || first == "-h") return false;
    return first.starts_with('-') || first.ends_with(".paper");
}

// A command after the editor's options ("paperfold --lang ko simulate ..."): it opened
// no editor (there was no display to open it on) and ran nothing. The word itself.
std::string_view commandAfterEditorOptions(int argc, char* argv[]) {
    for (int k = 1; k < argc; ++k)
        if (commandNamed(argv[k])) return argv[k];
    return {};
}

int runCommand(const QStringList& args, QTextStream& err) {
    try {
        const QByteArray word = args[1].toUtf8();
        if (const Command* c = commandNamed({word.constData(), std::size_t(word.size())}))
            return c->run(args);
        throw pf::cli::UsageError{QStringLiteral("unknown command '%1'").arg(args[1])};
    } catch (const pf::cli::UsageError& e) {
        err << "paperfold: " << e.message << '\n';
        return 1;
    } catch (const std::bad_alloc&) {
        // Under a memory limit (ulimit -v) a large export ended in "terminate called after
        // throwing 'std::bad_alloc'" and SIGABRT. What was being written was written whole
        // or not at all (OutputFile), so saying so is all there is to do.
        err << "paperfold: out of memory: the run needs more than this machine (or its "
               "limit) allows; try a lower --resolution, --subdiv or --size\n";
        return 2;
    }
}

// Qt reads the command line as UTF-8 and writes file names as UTF-8: a name in another
// encoding ("a\xff.paper") became "a\uFFFD.paper", so --save wrote a file of another
// name and --load found none. A name with a control character in it (a newline, an
// escape) was printed as it is: a result line split in two, a terminal's title set.
// Why an argument may not be used, or nothing if it may.
std::optional<QString> whyArgumentRefused(const char* argument) {
    const QByteArrayView bytes(argument);
    if (!bytes.isValidUtf8())
        return QStringLiteral("is not UTF-8 text; paperfold reads and writes file names in UTF-8, "
                              "so it would use another name than the one given");
    for (const QChar c : QString::fromUtf8(bytes))
        if (c.category() == QChar::Other_Control)
            return QStringLiteral("holds a control character (U+%1), which paperfold would print "
                                  "as it is")
                .arg(c.unicode(), 4, 16, QLatin1Char('0'));
    return std::nullopt;
}

// Qt's image readers say why a file is not a picture on the console ("qt.gui.imageio:
// ... allocation limit") before the command's own line says it again for the file it
// names: a headless command's errors are one line each.
QtMessageHandler qtsOwn = nullptr;
void leaveOutImageReaderMessages(QtMsgType type, const QMessageLogContext& context,
                                 const QString& message) {
    const bool imageReader =
        context.category && std::string_view(context.category).starts_with("qt.gui.imageio");
    if (imageReader && type != QtFatalMsg && type != QtCriticalMsg) return;
    if (qtsOwn)
        qtsOwn(type, context, message);
    else
        std::fprintf(stderr, "%s\n", qPrintable(qFormatLogMessage(type, context, message)));
}

} // namespace

int main(int argc, char* argv[]) {
    // A file-size limit (ulimit -f) killed the process mid-write with SIGXFSZ, with no
    // message and its temporary file left; ignored, the write fails with EFBIG, and the
    // writer says so and removes what it began.
    std::signal(SIGXFSZ, SIG_IGN);
    pf::removeUnfinishedOutputsOnSignals();
    for (int k = 1; k < argc; ++k)
        if (const auto why = whyArgumentRefused(argv[k])) {
            // Shown with its control characters and bad bytes made visible.
            QString shown;
            for (const QChar c : QString::fromUtf8(argv[k]))
                shown += c.category() == QChar::Other_Control
                             ? QStringLiteral("\\x%1").arg(c.unicode(), 2, 16, QLatin1Char('0'))
                             : QString(c);
            QTextStream(stderr) << "paperfold: argument " << k << " ('" << shown << "') " << *why
                                << ". Rename the file, or give the name in UTF-8 without "
                                   "control characters\n";
            return 1;
        }
    // No command (or only editor options and a file): the desktop editor.
    if (startsEditor(argc, argv)) {
        if (const std::string_view command = commandAfterEditorOptions(argc, argv);
            !command.empty()) {
            const QByteArray name(command.data(), qsizetype(command.size()));
            QTextStream(stderr) << "paperfold: '" << name
                                << "' must come first; the options before it are the editor's, and "
                                   "the commands speak English (paperfold "
                                << name << " --help lists its options)\n";
            return 1;
        }
        return pf::runEditor(argc, argv);
    }
    // Rendering draws legends with fonts, which need a GUI application; the
    // offscreen platform gives one with no display at all.
    const std::string_view command = argc >= 2 ? argv[1] : "";
    const bool gui = command == "render" || command == "replay" || command == "stability" ||
                     command == "bench" || command == "figures" || command == "crumple";
    if (gui && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    if (gui && qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        // The folder Qt would fall back to, made up front so it does not warn on stderr.
        const QByteArray dir = "/tmp/runtime-" + QByteArray::number(getuid());
        if (mkdir(dir.constData(), 0700) == 0 || errno == EEXIST) qputenv("XDG_RUNTIME_DIR", dir);
    }
    // Charts are widgets: bench needs a QApplication (still on the offscreen platform).
    std::unique_ptr<QCoreApplication> app = command == "bench"
                                                ? std::make_unique<QApplication>(argc, argv)
                                            : gui ? std::make_unique<QGuiApplication>(argc, argv)
                                                  : std::make_unique<QCoreApplication>(argc, argv);
    qtsOwn = qInstallMessageHandler(leaveOutImageReaderMessages);
    QCoreApplication::setApplicationName(QStringLiteral("paperfold"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_STRING));
    // The commands speak English: the numbers they draw (an image's legend) are written
    // in C's digits too, not in the user's (QLocale's default follows LANG).
    QLocale::setDefault(QLocale::c());
    const QStringList args = QCoreApplication::arguments();
    QTextStream out(stdout), err(stderr);
    if (args[1] == QLatin1String("--help") || args[1] == QLatin1String("-h") ||
        args[1] == QLatin1String("help")) {
        printUsage(out);
        out.flush();
        return pf::cli::checkOutputWritten(0);
    }
    return pf::cli::checkOutputWritten(runCommand(args, err));
}
