#include "RenderCases.h"

#include "JacobiScene.h"
#include "Scenes.h"
#include "Simulation.h"

#include <cmath>

namespace pf::test {

const std::vector<RenderCase>& renderCases() {
    static const std::vector<RenderCase> cases{
        {"press_iso", "press", 200, "iso", 0, 0, 0, 1.0, 0, 3},
        {"press_top_springs", "press", 200, "top", 0, 0, 0, 1.0,
         OverlaySpringKinds | OverlayRecentBreaks, 2},
        {"press_heatmaps", "press", 200, "", 20, 50, 0.45, 1.0,
         OverlayBreakProbability | OverlayStrain | OverlayWireframe, 3},
        {"drape_front", "drape", 240, "front", 0, 0, 0, 1.0, 0, 3},
        {"compress_iso_sigma0", "compress", 300, "iso", 0, 0, 0, 0.0, OverlayWireframe, 2},
        {"compress_iso_sigma1", "compress", 300, "iso", 0, 0, 0, 1.0, 0, 3},
        // A coarse, strongly curved mesh, where §4.3 subdivision and σ matter most.
        {"bumps_coarse_sigma1", "compress", 0, "", 30, 40, 0.42, 1.0, 0, 4, 8, 0.03},
        {"bumps_coarse_sigma0", "compress", 0, "", 30, 40, 0.42, 0.0, 0, 4, 8, 0.03},
        // The built-in paper grain through the material coordinates, close up.
        {"press_grain_close", "press", 200, "", 20, 50, 0.30, 1.0, 0, 3, 0, 0.0,
         PaperTexture::Grain},
    };
    return cases;
}

SheetSnapshot snapshotFor(const RenderCase& c) {
    SceneOptions options;
    options.resolution = c.resolution;
    // The pictures are of the renderer: the paper's jacobi crumples every scene's sheet
    // (xpbd's free press slides whole), so the baselines show creases and breaks.
    Simulation sim(jacobiScene(c.scene, options));
    for (int k = 0; k < c.steps; ++k) sim.step();
    for (Vec3& p : sim.world().sheet.verts.x)
        p.y() += c.bumps * (1.0 + std::sin(31.0 * p.x()) * std::cos(23.0 * p.z()));
    sim.sheetEdited();
    return makeSnapshot(sim);
}

OrbitCamera cameraFor(const RenderCase& c, const SheetSnapshot& snap, double aspect) {
    OrbitCamera cam = namedView(*c.view ? c.view : "iso").value();
    cam.fitPoints(snap.x, aspect);
    if (!*c.view) {
        cam.yaw = c.yaw;
        cam.pitch = c.pitch;
        cam.distance = c.distance;
    }
    return cam;
}

RenderOptions optionsFor(const RenderCase& c) {
    RenderOptions o;
    o.sigma = c.sigma;
    o.overlays = c.overlays;
    o.subdivision = c.subdivision;
    o.look.texture = c.texture;
    return o;
}

} // namespace pf::test
