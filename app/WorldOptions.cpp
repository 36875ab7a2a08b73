#include "WorldOptions.h"

#include "CommandLine.h"
#include "Integrator.h"
#include "Scenes.h"
#include "SheetFile.h"

#include <QStringList>

namespace pf::cli {

namespace {

QString joined(const std::vector<std::string>& names) {
    QStringList list;
    for (const auto& n : names) list << QString::fromStdString(n);
    return list.join(QStringLiteral(", "));
}

} // namespace

void addWorldOptions(QCommandLineParser& parser) {
    parser.addOptions({
        {QStringLiteral("scene"),
         QStringLiteral("Start from a scene: %1.").arg(joined(sceneNames())),
         QStringLiteral("name")},
        {QStringLiteral("load"), QStringLiteral("Start from a saved .paper sheet."),
         QStringLiteral("file")},
        {QStringLiteral("seed"), QStringLiteral("Random seed of a new scene (default 1)."),
         QStringLiteral("s")},
        {QStringLiteral("resolution"),
         QStringLiteral("Vertices along a new scene's short side (%1-%2).")
             .arg(kMinResolution)
             .arg(kMaxResolution),
         QStringLiteral("n")},
        {QStringLiteral("phi"), QStringLiteral("Fragility φ in [0, 1]."), QStringLiteral("f")},
        {QStringLiteral("psi"), QStringLiteral("Recursive-break tendency ψ in [0, 1]."),
         QStringLiteral("f")},
        {QStringLiteral("sigma"),
         QStringLiteral("Crumple smoothing σ in [0, 4] (rendering: 0 keeps flat facets and sharp "
                        "creases, larger rounds them off)."),
         QStringLiteral("f")},
        {QStringLiteral("integrator"),
         QStringLiteral("Integrator: %1.").arg(joined(integratorNames())), QStringLiteral("name")},
        {QStringLiteral("iterations"),
         QStringLiteral("Jacobi sweeps after the first estimate (jacobi, jacobi-scalar)."),
         QStringLiteral("k")},
        {QStringLiteral("dt"), QStringLiteral("Time step in seconds."), QStringLiteral("h")},
        {QStringLiteral("material"),
         QStringLiteral("Paper: %1 (its weight; for xpbd also its stiffness, bending and "
                        "friction).")
             .arg(joined(materialNames())),
         QStringLiteral("name")},
        {QStringLiteral("substeps"), QStringLiteral("Sub-steps per step (xpbd, 1-1000)."),
         QStringLiteral("n")},
        {QStringLiteral("no-self-contact"),
         QStringLiteral("Let the paper's layers pass through each other (xpbd).")},
        {QStringLiteral("gravity-outside-filter"),
         QStringLiteral("Integrate gravity outside the implicit filter (jacobi, "
                        "jacobi-scalar; the paper's Eq. 6 divides it by W).")},
    });
}

World worldFromOptions(const QCommandLineParser& parser) {
    const bool load = parser.isSet(QStringLiteral("load"));
    if (load && parser.isSet(QStringLiteral("scene")))
        throw UsageError{QStringLiteral("--scene and --load exclude each other")};
    std::optional<World> world;
    if (load) {
        for (const char* sceneOnly : {"seed", "resolution"})
            if (parser.isSet(QLatin1String(sceneOnly)))
                throw UsageError{QStringLiteral("--%1 applies to a new --scene, not to --load")
                                     .arg(QLatin1String(sceneOnly))};
        WorldLoad loaded = loadWorld(parser.value(QStringLiteral("load")));
        if (!loaded.world) throw UsageError{loaded.error};
        world = std::move(loaded.world);
    } else {
        SceneOptions options;
        if (auto r =
                integerOption(parser, QStringLiteral("resolution"), kMinResolution, kMaxResolution))
            options.resolution = static_cast<int>(*r);
        if (auto s = seedOption(parser, QStringLiteral("seed"))) options.seed = *s;
        const QString name = parser.isSet(QStringLiteral("scene"))
                                 ? parser.value(QStringLiteral("scene"))
                                 : QStringLiteral("press");
        world = makeScene(name.toStdString(), options);
        if (!world)
            throw UsageError{
                QStringLiteral("unknown scene '%1' (known: %2)").arg(name, joined(sceneNames()))};
    }

    SimParams& p = world->params;
    if (auto v = realOption(parser, QStringLiteral("phi"), 0.0, 1.0)) p.phi = *v;
    if (auto v = realOption(parser, QStringLiteral("psi"), 0.0, 1.0)) p.psi = *v;
    if (auto v = realOption(parser, QStringLiteral("sigma"), 0.0, 4.0)) p.sigma = *v;
    if (auto v = realOption(parser, QStringLiteral("dt"), 1e-7, 0.1)) p.dt = *v;
    if (auto v = integerOption(parser, QStringLiteral("iterations"), 0, 1000))
        p.iterations = static_cast<int>(*v);
    if (parser.isSet(QStringLiteral("gravity-outside-filter"))) p.gravityOutsideFilter = true;
    if (parser.isSet(QStringLiteral("no-self-contact"))) p.selfContact = false;
    if (auto v = integerOption(parser, QStringLiteral("substeps"), 1, 1000))
        p.substeps = static_cast<int>(*v);
    if (parser.isSet(QStringLiteral("material"))) {
        const QString name = parser.value(QStringLiteral("material"));
        Material m;
        if (!materialPreset(name.toStdString(), m))
            throw UsageError{QStringLiteral("unknown material '%1' (known: %2)")
                                 .arg(name, joined(materialNames()))};
        setMaterial(*world, m);
    }
    if (parser.isSet(QStringLiteral("integrator"))) {
        p.integrator = integratorOption(parser);
    }
    refuseOptionsTheIntegratorIgnores(parser, p.integrator);
    return std::move(*world);
}

QStringList worldInputs(const QCommandLineParser& parser) {
    if (!parser.isSet(QStringLiteral("load"))) return {};
    return {parser.value(QStringLiteral("load"))};
}

} // namespace pf::cli
