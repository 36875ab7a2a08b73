#include "SimulateCommand.h"

#include "CommandLine.h"
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <cstdio>

namespace pf::cli {

namespace {

QString joined(const std::vector<std::string>& names) {
    QStringList list;
    for (const auto& n : names) list << QString::fromStdString(n);
    return list.join(QStringLiteral(", "));
}

QJsonObject statsJson(const Simulation& sim, double wallSeconds, long long steps) {
    const World& w = sim.world();
    const SheetStats st = computeStats(w.sheet);
    QJsonObject o;
    o[QStringLiteral("scene")] = QString::fromStdString(w.scene);
    o[QStringLiteral("integrator")] = QString::fromStdString(w.params.integrator);
    o[QStringLiteral("iterations")] = w.params.iterations;
    o[QStringLiteral("dt")] = w.params.dt;
    o[QStringLiteral("seed")] = QString::number(w.seed);
    o[QStringLiteral("steps")] = steps;
    o[QStringLiteral("vertices")] = st.vertices;
    o[QStringLiteral("springs")] = st.springs;
    o[QStringLiteral("triangles")] = st.triangles;
    o[QStringLiteral("breaks")] = st.breaks;
    o[QStringLiteral("recoveries")] = st.recoveries;
    o[QStringLiteral("hinges")] = st.hinges;
    o[QStringLiteral("total_mass")] = st.totalMass;
    o[QStringLiteral("max_strain")] = st.maxStrain;
    o[QStringLiteral("rms_strain")] = st.rmsStrain;
    // Hex text: a 64-bit hash does not survive JSON's double-precision numbers.
    o[QStringLiteral("state_hash")] =
        QStringLiteral("%1").arg(stateHash(w.sheet), 16, 16, QLatin1Char('0'));
    o[QStringLiteral("sim_time")] = w.time;
    o[QStringLiteral("wall_seconds")] = wallSeconds;
    o[QStringLiteral("steps_per_second")] = wallSeconds > 0.0 ? steps / wallSeconds : 0.0;
    return o;
}

} // namespace

int runSimulate(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Run a scene headless and report statistics."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("simulate"), QStringLiteral("The subcommand."));
    parser.addOptions({
        {QStringLiteral("scene"), QStringLiteral("Scene: %1.").arg(joined(sceneNames())),
         QStringLiteral("name"), QStringLiteral("press")},
        {QStringLiteral("steps"), QStringLiteral("Number of steps (default 600)."),
         QStringLiteral("n")},
        {QStringLiteral("seed"), QStringLiteral("Random seed (default 1)."), QStringLiteral("s")},
        {QStringLiteral("phi"), QStringLiteral("Fragility φ in [0, 1]."), QStringLiteral("f")},
        {QStringLiteral("psi"), QStringLiteral("Recursive-break tendency ψ in [0, 1]."),
         QStringLiteral("f")},
        {QStringLiteral("integrator"),
         QStringLiteral("Integrator: %1.").arg(joined(integratorNames())), QStringLiteral("name")},
        {QStringLiteral("iterations"), QStringLiteral("Jacobi sweeps after the first estimate."),
         QStringLiteral("k")},
        {QStringLiteral("dt"), QStringLiteral("Time step in seconds."), QStringLiteral("h")},
        {QStringLiteral("resolution"),
         QStringLiteral("Vertices along the short side (%1-%2).")
             .arg(kMinResolution)
             .arg(kMaxResolution),
         QStringLiteral("n")},
        {QStringLiteral("stats"), QStringLiteral("Print statistics as one JSON object.")},
    });
    if (!parser.parse(arguments)) throw UsageError{parser.errorText()};
    if (parser.isSet(QStringLiteral("help"))) {
        QTextStream(stdout) << parser.helpText();
        return 0;
    }
    rejectExtraArguments(parser, 1);

    SceneOptions sceneOptions;
    if (auto r =
            integerOption(parser, QStringLiteral("resolution"), kMinResolution, kMaxResolution))
        sceneOptions.resolution = static_cast<int>(*r);
    if (auto s = seedOption(parser, QStringLiteral("seed"))) sceneOptions.seed = *s;
    const QString sceneName = parser.value(QStringLiteral("scene"));
    std::optional<World> world = makeScene(sceneName.toStdString(), sceneOptions);
    if (!world)
        throw UsageError{
            QStringLiteral("unknown scene '%1' (known: %2)").arg(sceneName, joined(sceneNames()))};

    SimParams& p = world->params;
    if (auto v = realOption(parser, QStringLiteral("phi"), 0.0, 1.0)) p.phi = *v;
    if (auto v = realOption(parser, QStringLiteral("psi"), 0.0, 1.0)) p.psi = *v;
    if (auto v = realOption(parser, QStringLiteral("dt"), 1e-7, 0.1)) p.dt = *v;
    if (auto v = integerOption(parser, QStringLiteral("iterations"), 0, 1000))
        p.iterations = static_cast<int>(*v);
    if (parser.isSet(QStringLiteral("integrator"))) {
        const QString name = parser.value(QStringLiteral("integrator"));
        if (!makeIntegrator(name.toStdString()))
            throw UsageError{QStringLiteral("unknown integrator '%1' (known: %2)")
                                 .arg(name, joined(integratorNames()))};
        p.integrator = name.toStdString();
    }
    const long long steps =
        integerOption(parser, QStringLiteral("steps"), 0, 1'000'000'000).value_or(600);

    Simulation sim(std::move(*world));
    QElapsedTimer timer;
    timer.start();
    long long done = 0;
    bool diverged = false;
    for (; done < steps; ++done) {
        if (sim.step() != StepStatus::Ok) {
            diverged = true;
            break;
        }
    }
    const double wall = static_cast<double>(timer.nsecsElapsed()) * 1e-9;

    QJsonObject stats = statsJson(sim, wall, done);
    stats[QStringLiteral("diverged")] = diverged;
    if (parser.isSet(QStringLiteral("stats"))) {
        QTextStream(stdout) << QJsonDocument(stats).toJson(QJsonDocument::Compact) << '\n';
    } else {
        QTextStream(stdout) << QStringLiteral("%1: %2 steps, %3 breaks, %4 hinges, %5 steps/s\n")
                                   .arg(sceneName)
                                   .arg(done)
                                   .arg(stats[QStringLiteral("breaks")].toInt())
                                   .arg(stats[QStringLiteral("hinges")].toInt())
                                   .arg(stats[QStringLiteral("steps_per_second")].toDouble(), 0,
                                        'f', 0);
    }
    if (diverged) {
        QTextStream(stderr)
            << QStringLiteral("paperfold: the simulation diverged at step %1 (non-finite or "
                              "exploding state); try a smaller --dt or an implicit integrator\n")
                   .arg(done + 1);
        return 3;
    }
    return 0;
}

} // namespace pf::cli
