#pragma once

#include "Camera.h"
#include "RenderOptions.h"
#include "SheetSnapshot.h"
#include "SurfaceExport.h"

#include <QString>

namespace pf {

// What the editor's File ▸ Export writes: the picture as the viewport frames it, at any
// size, through OSMesa; and the surface as drawn (σ, subdivision level), as a mesh file.
bool exportSnapshotImage(const SheetSnapshot& snap, const OrbitCamera& camera,
                         const RenderOptions& options, int width, int height, const QString& path,
                         QString* error);
bool exportSnapshotMesh(const SheetSnapshot& snap, const RenderOptions& options,
                        const QString& path, MeshFormat format, QString* error);

} // namespace pf
