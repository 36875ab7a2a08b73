#include "ExportCommand.h"

#include "CommandLine.h"
#include "LookOptions.h"
#include "Simulation.h"
#include "Subdivision.h"
#include "SurfaceExport.h"
#include "WorldOptions.h"

#include <QFileInfo>
#include <QTextStream>

namespace pf::cli {

int runExport(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Write a sheet's subdivided surface (paper §4.3) as .obj, .ply or .glb for a 3D package."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("export"), QStringLiteral("The subcommand."));
    addWorldOptions(parser);
    parser.addOptions({
        {QStringLiteral("steps"), QStringLiteral("Steps to simulate before exporting (default 0)."),
         QStringLiteral("n")},
        {QStringLiteral("output"), QStringLiteral("Output file: .obj, .ply or .glb."),
         QStringLiteral("file")},
        {QStringLiteral("subdiv"),
         QStringLiteral("Subdivision level 0-%1 (default 2).").arg(kMaxSubdivisionLevel),
         QStringLiteral("level")},
        {QStringLiteral("no-normals"), QStringLiteral("Leave vertex normals out.")},
    });
    addLookOptions(parser);
    if (!parseCommand(parser, arguments)) return 0;
    if (!parser.isSet(QStringLiteral("output")))
        throw UsageError{QStringLiteral("--output is required (a .obj, .ply or .glb file)")};
    const QString output = parser.value(QStringLiteral("output"));
    MeshFormat format;
    if (!meshFormatForPath(output, &format))
        throw UsageError{
            QStringLiteral("--output: '%1' does not end in .obj, .ply or .glb").arg(output)};
    QStringList inputs = worldInputs(parser);
    const PaperLook look = lookFromOptions(parser, &inputs);
    // Only a GLB carries the look; elsewhere it was taken without a word.
    if (format != MeshFormat::Glb &&
        (parser.isSet(QStringLiteral("texture")) || parser.isSet(QStringLiteral("paper-color"))))
        QTextStream(stderr) << "paperfold: note: a ." << QFileInfo(output).suffix().toLower()
                            << " file carries no paper colour or texture (a .glb does); "
                               "--paper-color and --texture are left out\n";
    requireWritable(QStringLiteral("output"), output, inputs);
    const int level = static_cast<int>(
        integerOption(parser, QStringLiteral("subdiv"), 0, kMaxSubdivisionLevel).value_or(2));
    const long long steps =
        integerOption(parser, QStringLiteral("steps"), 0, 1'000'000'000).value_or(0);

    Simulation sim(worldFromOptions(parser));
    for (long long k = 0; k < steps; ++k)
        if (sim.step() != StepStatus::Ok) {
            QTextStream(stderr) << "paperfold: the simulation diverged at step " << k + 1
                                << "; nothing was exported\n";
            return 3;
        }
    SurfaceMesh mesh = subdivideSheet(sim.world().sheet, sim.world().params.sigma, level);
    if (sim.world().groundEnabled) liftOntoTheDesk(mesh, sim.world().groundHeight);
    QString error;
    if (!writeSurface(mesh, output, format, !parser.isSet(QStringLiteral("no-normals")),
                      surfaceLook(look), &error, inputs)) {
        QTextStream(stderr) << "paperfold: " << error << '\n';
        return 2;
    }
    QTextStream(stdout) << QStringLiteral("%1: %2 vertices, %3 triangles\n")
                               .arg(output)
                               .arg(mesh.positions.size())
                               .arg(mesh.triangles.size());
    return 0;
}

} // namespace pf::cli
