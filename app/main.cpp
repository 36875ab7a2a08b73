#include "CommandLine.h"
#include "ExportCommand.h"
#include "SimulateCommand.h"

#include <QCoreApplication>
#include <QTextStream>

namespace {

void printUsage(QTextStream& out) {
    out << "usage: paperfold <command> [options]\n"
           "\n"
           "commands:\n"
           "  simulate   run a scene or a saved sheet headless; report statistics, save\n"
           "  export     write the subdivided surface as .obj, .ply or .glb\n"
           "\n"
           "paperfold <command> --help lists a command's options.\n"
           "\n"
           "The desktop editor is not built yet; see README.md.\n";
}

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("paperfold"));
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_STRING));
    const QStringList args = QCoreApplication::arguments();
    QTextStream out(stdout), err(stderr);
    if (args.size() < 2 || args[1] == QLatin1String("--help") || args[1] == QLatin1String("-h")) {
        printUsage(args.size() < 2 ? err : out);
        return args.size() < 2 ? 1 : 0;
    }
    try {
        if (args[1] == QLatin1String("simulate")) return pf::cli::runSimulate(args);
        if (args[1] == QLatin1String("export")) return pf::cli::runExport(args);
        throw pf::cli::UsageError{QStringLiteral("unknown command '%1'").arg(args[1])};
    } catch (const pf::cli::UsageError& e) {
        err << "paperfold: " << e.message << '\n';
        return 1;
    }
}
