#pragma once

#include "Subdivision.h"

#include <QString>
#include <QStringList>

namespace pf {

enum class MeshFormat { Obj, Ply, Glb };

// The format named by a file's extension (.obj, .ply, .glb), if any.
bool meshFormatForPath(const QString& path, MeshFormat* format);

// Writes the surface through the checked output path (OutputFile.h): atomic, and never
// over a device or one of `inputs`. Positions in metres, y up: what Blender's OBJ, PLY
// and glTF importers expect.
bool writeSurface(const SurfaceMesh& mesh, const QString& path, MeshFormat format, bool withNormals,
                  QString* error, const QStringList& inputs = {});

} // namespace pf
