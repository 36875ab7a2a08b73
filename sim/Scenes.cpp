#include "Scenes.h"

#include "FoldPlan.h"
#include "Rng.h"
#include "SheetBuilder.h"

#include <cmath>
#include <numbers>

namespace pf {

namespace {

constexpr int kDefaultResolution = 19; // 494 vertices, as in the paper's Fig. 13

SheetSpec sceneSpec(const SceneOptions& options) {
    return sizedSpec(options.resolution > 0 ? options.resolution : kDefaultResolution,
                     options.width, options.length);
}

World baseWorld(std::string_view name, const SceneOptions& options, double height) {
    World w;
    w.scene = std::string(name);
    w.seed = options.seed;
    w.rng.reseed(options.seed);
    SheetSpec spec = sceneSpec(options);
    spec.height = height;
    w.sheet = buildRectangleSheet(spec);
    return w;
}

Index vertexAt(const SheetSpec& spec, int column, int row) {
    return row * spec.columns + column;
}

World pressScene(const SceneOptions& options) {
    World w = baseWorld("press", options, 0.0);
    // The sphere comes down near one end and ploughs an S along the long axis,
    // reaching below the sheet's level so that it catches the paper and shoves it
    // together ahead of itself (compression is what breaks springs), then lifts off.
    const double R = 0.04;
    const double low = R - 0.01;
    w.sphere.radius = R;
    w.script.sphereKeys = {{0.0, Vec3(0.03, 0.12, -0.11)},
                           {0.15, Vec3(0.03, low, -0.11)},
                           {0.45, Vec3(-0.03, low, -0.02)},
                           {0.75, Vec3(0.03, low, 0.07)},
                           {0.95, Vec3(0.03, 0.12, 0.07)}};
    w.sphere.center = w.script.sphereKeys.front().center;
    w.sphere.active = true;
    return w;
}

World drapeScene(const SceneOptions& options) {
    World w = baseWorld("drape", options, 0.35);
    w.params.breaking = false;
    const SheetSpec spec = sceneSpec(options);
    PinGroup corners;
    corners.vertices = {vertexAt(spec, 0, 0), vertexAt(spec, spec.columns - 1, 0)};
    for (Index i : corners.vertices) w.sheet.verts.pinned[i] = 1;
    w.script.pins.push_back(corners);
    return w;
}

World compressScene(const SceneOptions& options) {
    World w = baseWorld("compress", options, 0.0);
    const SheetSpec spec = sceneSpec(options);
    // A faint arch seeds the buckling direction so the sheet rises off the ground.
    for (int r = 0; r < spec.rows; ++r)
        for (int c = 0; c < spec.columns; ++c)
            w.sheet.verts.x[vertexAt(spec, c, r)].y() =
                0.002 * std::sin(std::numbers::pi * r / (spec.rows - 1));
    // Both short edges move inward at 4 cm/s for 1.5 s: 40 % of the length in total.
    PinGroup nearEdge, farEdge;
    nearEdge.velocity = Vec3(0.0, 0.0, 0.04);
    farEdge.velocity = Vec3(0.0, 0.0, -0.04);
    nearEdge.until = farEdge.until = 1.5;
    for (int c = 0; c < spec.columns; ++c) {
        nearEdge.vertices.push_back(vertexAt(spec, c, 0));
        farEdge.vertices.push_back(vertexAt(spec, c, spec.rows - 1));
    }
    for (const PinGroup* g : {&nearEdge, &farEdge})
        for (Index i : g->vertices) w.sheet.verts.pinned[i] = 1;
    w.script.pins = {nearEdge, farEdge};
    return w;
}

World foldScene(const SceneOptions& options) {
    World w = baseWorld("fold", options, 0.0);
    // The near half is folded over onto the far one across the middle as the Fold tool
    // folds (sim/FoldPlan.h): carried round as a hand carries it, held pressed flat, and
    // let go; the crease forms in the band along the line, where the paper bends.
    // A sphere rolled along the fold pressed a crease into the soft springs of the
    // paper's model, but stiff paper stands a loose fold up in a loop centimetres tall,
    // which a sphere rolled along it pushes aside rather than presses. A sheet too short
    // to have paper beyond the band on both sides is not folded: it lies on the desk.
    const double reach = 0.5 * options.width + 0.01;
    FoldPlan plan = planFold(w, {Vec3(-reach, 0.0, 0.0), Vec3(reach, 0.0, 0.0)});
    for (PinGroup& g : plan.motions) {
        for (Index i : g.vertices) w.sheet.verts.pinned[i] = 1;
        w.script.pins.push_back(std::move(g));
    }
    return w;
}

World crumpleCyclesScene(const SceneOptions& options) {
    World w = baseWorld("crumple-cycles", options, 0.0);
    const SheetSpec spec = sceneSpec(options);
    // A faint dome seeds the first buckling upward, off the desk.
    std::vector<Index> rim;
    for (int r = 0; r < spec.rows; ++r)
        for (int c = 0; c < spec.columns; ++c) {
            const Index i = vertexAt(spec, c, r);
            w.sheet.verts.x[i].y() = 0.002 * std::sin(std::numbers::pi * r / (spec.rows - 1)) *
                                     std::sin(std::numbers::pi * c / (spec.columns - 1));
            if (r == 0 || c == 0 || r == spec.rows - 1 || c == spec.columns - 1) rim.push_back(i);
        }
    for (Index i : rim) w.sheet.verts.pinned[i] = 1;
    // Each cycle gathers the rim toward a point of the middle half of the sheet, a new
    // one each cycle as hands never crumple twice alike, to kCrumpleFraction of its
    // size; holds it; pulls it out flat again and holds it there. The points are the
    // scene's own draws, so the world's generator (the breaks') is the seed's as in
    // every scene.
    Rng centres(options.seed ^ 0x9e3779b97f4a7c15ULL);
    const double rate = std::log(kCrumpleFraction) / kCrumpleGather;
    for (int k = 0; k < kCrumpleCycles; ++k) {
        const double begin = k * kCrumpleCycleSeconds;
        PinGroup gather;
        gather.vertices = rim;
        gather.pivot = Vec3((centres.uniform() - 0.5) * 0.5 * options.width, 0.0,
                            (centres.uniform() - 0.5) * 0.5 * options.length);
        gather.scaleRate = rate;
        gather.start = begin;
        gather.until = begin + kCrumpleGather;
        PinGroup pull = gather;
        pull.scaleRate = -rate;
        pull.start = gather.until + kCrumpleSqueeze;
        pull.until = pull.start + kCrumpleGather;
        w.script.pins.push_back(std::move(gather));
        w.script.pins.push_back(std::move(pull));
    }
    return w;
}

World dropScene(const SceneOptions& options) {
    World w = baseWorld("drop", options, 0.0);
    // Tilted 45° about x, its lower edge 4.5 cm above the ground: springs lie along
    // gravity, so this is where the paper's step visibly holds the sheet up
    // (docs/solver-lab.md), and the landing crumples it.
    for (Vec3& x : w.sheet.verts.x) {
        const double z = x.z();
        x = Vec3(x.x(), 0.15 + z * std::sin(std::numbers::pi / 4),
                 z * std::cos(std::numbers::pi / 4));
    }
    return w;
}

} // namespace

void setMaterial(World& world, const Material& material) {
    Sheet& sheet = world.sheet;
    const double scale = material.arealDensity / sheet.density;
    for (double& m : sheet.verts.m) m *= scale;
    for (DamageEvent& ev : sheet.events)
        for (double& taken : ev.massTaken) taken *= scale;
    sheet.density = material.arealDensity;
    if (!(world.params.material == material)) sheet.paper.meshChanged();
    world.params.material = material;
}

const std::vector<std::string>& sceneNames() {
    static const std::vector<std::string> names{"press", "drape", "compress",
                                                "drop",  "fold",  "crumple-cycles"};
    return names;
}

std::optional<World> makeScene(std::string_view name, const SceneOptions& options) {
    if (options.resolution != 0 &&
        (options.resolution < kMinResolution || options.resolution > kMaxResolution))
        return std::nullopt;
    for (const double side : {options.width, options.length})
        if (!(side >= kMinSheetSide && side <= kMaxSheetSide)) return std::nullopt;
    if (name == "press") return pressScene(options);
    if (name == "drape") return drapeScene(options);
    if (name == "compress") return compressScene(options);
    if (name == "drop") return dropScene(options);
    if (name == "fold") return foldScene(options);
    if (name == "crumple-cycles") return crumpleCyclesScene(options);
    return std::nullopt;
}

World makeEditorScene(std::string_view name, const SceneOptions& options, double toolRadius) {
    std::optional<World> scene = makeScene(name, options);
    if (!scene) scene = makeScene("press", options);
    World w = std::move(scene).value();
    w.script.sphereKeys.clear();
    w.params.gravityOutsideFilter = true;
    w.sphere.radius = toolRadius;
    w.sphere.active = false;
    return w;
}

} // namespace pf
