#include "DrawnSurface.h"

#include "HeatColor.h"
#include "Subdivision.h"

#include <algorithm>

namespace pf {

namespace {

template <typename T> void clearFor(std::vector<T>& v, std::size_t size) {
    if (v.capacity() > 2 * size) std::vector<T>().swap(v);
    v.clear();
    v.reserve(size);
}

} // namespace

SurfaceKey surfaceKeyOf(const SheetSnapshot& snapshot, const RenderOptions& options) {
    const bool strain = options.overlays & OverlayStrain;
    return {snapshot.serial, options.subdivision, options.sigma, options.strainRange, strain};
}

void buildDrawnSurface(const SheetSnapshot& snap, const RenderOptions& options, DrawnSurface& out) {
    out.key = surfaceKeyOf(snap, options);
    const bool strain = out.key.strain;
    SurfaceMesh mesh = subdivide(snap.x, snap.tris, strain ? &snap.vertexStrain : nullptr, &snap.X,
                                 options.sigma, options.subdivision);
    if (snap.groundEnabled) liftOntoTheDesk(mesh, snap.groundHeight);
    out.hasUvs = !mesh.uvs.empty();
    clearFor(out.vertices, mesh.positions.size() * DrawnSurface::kFloatsPerVertex);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        const Vec3& n = mesh.normals[i];
        out.vertices.insert(out.vertices.end(), {float(p.x()), float(p.y()), float(p.z()),
                                                 float(n.x()), float(n.y()), float(n.z())});
        if (strain) {
            const auto c = heatColor(mesh.scalars[i] / options.strainRange);
            out.vertices.insert(out.vertices.end(), {c[0], c[1], c[2], 1.0f});
        } else {
            out.vertices.insert(out.vertices.end(), {0.0f, 0.0f, 0.0f, 0.0f});
        }
        if (out.hasUvs)
            out.vertices.insert(out.vertices.end(),
                                {float(mesh.uvs[i].x()), float(mesh.uvs[i].y())});
        else
            out.vertices.insert(out.vertices.end(), {0.0f, 0.0f});
    }
    clearFor(out.indices, mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles) out.indices.insert(out.indices.end(), t.begin(), t.end());
}

RenderOptions interactiveOptions(const RenderOptions& options, std::size_t simulationTriangles) {
    RenderOptions drawn = options;
    drawn.subdivision =
        subdivisionWithin(options.subdivision, simulationTriangles, kInteractiveTriangles);
    return drawn;
}

} // namespace pf
