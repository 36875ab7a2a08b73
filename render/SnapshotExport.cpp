#include "SnapshotExport.h"

#include "OffscreenRenderer.h"
#include "PngFile.h"
#include "Subdivision.h"

namespace pf {

bool exportSnapshotImage(const SheetSnapshot& snap, const OrbitCamera& camera,
                         const RenderOptions& options, int width, int height, const QString& path,
                         QString* error) {
    auto renderer = OffscreenRenderer::create(width, height, error);
    if (!renderer) return false;
    return writePng(renderer->render(snap, camera, options), path, error);
}

bool exportSnapshotMesh(const SheetSnapshot& snap, const RenderOptions& options,
                        const QString& path, MeshFormat format, QString* error) {
    SurfaceMesh mesh =
        subdivide(snap.x, snap.tris, nullptr, &snap.X, options.sigma, options.subdivision);
    if (snap.groundEnabled) liftOntoTheDesk(mesh, snap.groundHeight);
    return writeSurface(mesh, path, format, true, surfaceLook(options.look), error);
}

} // namespace pf
