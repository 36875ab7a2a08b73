#pragma once

#include "Subdivision.h"

#include <QString>
#include <QStringList>
#include <array>

namespace pf {

enum class MeshFormat { Obj, Ply, Glb };

// The paper's look as a mesh file carries it. GLB: the colour (sRGB, as shown) as
// baseColorFactor, converted to the linear light glTF asks for, and the texture (PNG
// bytes; empty for none) as baseColorTexture. OBJ and PLY carry only the
// texture coordinates.
// Office paper's off-white, sRGB: the look's default colour.
inline constexpr std::array<float, 3> kPaperColor = {0.95f, 0.94f, 0.90f};

struct SurfaceLook {
    std::array<float, 3> color = kPaperColor;
    QByteArray texturePng;
};

// The format named by a file's extension (.obj, .ply, .glb), if any.
bool meshFormatForPath(const QString& path, MeshFormat* format);

// Writes the surface through the checked output path (OutputFile.h): atomic, and never
// over a device or one of `inputs`. Positions in metres, y up: what Blender's OBJ, PLY
// and glTF importers expect. Texture coordinates, when the mesh has them: glTF's as the
// mesh holds them (image origin top-left); OBJ's `vt` and PLY's `s t` with v flipped
// (1 - v), since those formats put the image's origin at its bottom-left.
bool writeSurface(const SurfaceMesh& mesh, const QString& path, MeshFormat format, bool withNormals,
                  const SurfaceLook& look, QString* error, const QStringList& inputs = {});

} // namespace pf
