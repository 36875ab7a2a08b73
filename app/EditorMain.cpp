#include "EditorMain.h"

#include "DisplayCheck.h"
#include "Language.h"
#include "MainWindow.h"
#include "Viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTextStream>

namespace pf {

int runEditor(int argc, char* argv[]) {
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
    QCoreApplication::setOrganizationName(QStringLiteral("PaperFold"));
    QCoreApplication::setApplicationName(QStringLiteral("PaperFold"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_STRING));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("PaperFold: crumple and fold virtual paper."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addOption(
        {QStringLiteral("lang"),
         QStringLiteral("Interface language: en, de, ja or ko (default: the system's)."),
         QStringLiteral("code")});
    parser.addPositionalArgument(QStringLiteral("sheet"), QStringLiteral("A .paper file to open."));
    parser.process(app);

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
