#include "EditorMain.h"

#include "CommandLine.h"
#include "DisplayCheck.h"
#include "Language.h"
#include "MainWindow.h"
#include "Viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QOpenGLContext>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTextStream>
#include <cstdlib>
#include <string_view>

namespace pf {

namespace {

void addEditorOptions(QCommandLineParser& parser) {
    parser.setApplicationDescription(QStringLiteral("PaperFold: crumple and fold virtual paper."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption(
        {QStringLiteral("lang"),
         QStringLiteral("Interface language: en, de, ja or ko (default: the system's)."),
         QStringLiteral("code")});
    parser.addPositionalArgument(QStringLiteral("sheet"), QStringLiteral("A .paper file to open."));
}

void nameApplication() {
    QCoreApplication::setOrganizationName(QStringLiteral("PaperFold"));
    QCoreApplication::setApplicationName(QStringLiteral("PaperFold"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_STRING));
}

// --help and --version print and end: they need no display ("paperfold --version" over
// ssh said the editor needs one).
bool asksOnlyForText(int argc, char* argv[]) {
    for (int k = 1; k < argc; ++k) {
        const std::string_view a = argv[k];
        if (a == "--help" || a == "-h" || a == "--help-all" || a == "--version" || a == "-v")
            return true;
    }
    return false;
}

} // namespace

int runEditor(int argc, char* argv[]) {
    if (asksOnlyForText(argc, argv)) {
        QCoreApplication app(argc, argv);
        nameApplication();
        QCommandLineParser parser;
        addEditorOptions(parser);
        // process() prints and exits: the text lost to a full disk said nothing, exit 0.
        std::atexit([] {
            if (const int code = cli::checkOutputWritten(0); code != 0) std::_Exit(code);
        });
        parser.process(app);
        return 0;
    }
    if (const QString problem = displayProblem(); !problem.isEmpty()) {
        QTextStream(stderr) << "paperfold: " << problem
                            << ".\nRun it in a desktop session, or use the headless commands "
                               "(paperfold --help lists them; render needs no display).\n";
        return 2;
    }
    // Every GL context (the viewport's) must be 3.3 core; set before the app exists.
    QSurfaceFormat::setDefaultFormat(Viewport::requiredFormat());
    Viewport::prepareProcess();
    QApplication app(argc, argv);
    nameApplication();
    QCommandLineParser parser;
    addEditorOptions(parser);
    parser.process(app);
    // A platform with no OpenGL (QT_QPA_PLATFORM=offscreen, minimal or vnc) let the
    // window be made and crashed in its first paint (SIGSEGV).
    QOpenGLContext probe;
    probe.setFormat(Viewport::requiredFormat());
    if (!probe.create()) {
        QTextStream(stderr) << "paperfold: the editor draws with OpenGL "
                            << Viewport::requiredFormat().majorVersion() << '.'
                            << Viewport::requiredFormat().minorVersion() << ", and the platform '"
                            << QGuiApplication::platformName()
                            << "' gives no OpenGL context.\nRun it in a desktop session, or use "
                               "the headless commands (paperfold --help lists them).\n";
        return 2;
    }

    const QString lang = parser.isSet(QStringLiteral("lang"))
                             ? parser.value(QStringLiteral("lang"))
                             : QSettings().value(QStringLiteral("language")).toString();
    if (!installLanguage(lang))
        QTextStream(stderr) << "paperfold: no translation for '" << lang << "'; using English\n";

    MainWindow window;
    window.show();
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().first());
    return app.exec();
}

} // namespace pf
