#pragma once

#include "SurfaceExport.h"

#include <QImage>
#include <QString>
#include <array>
#include <optional>

namespace pf {

// What the paper looks like (not what it does): a colour, and a texture over the whole
// sheet through the material coordinates. The colour multiplies the texture, as glTF's
// baseColorFactor multiplies its baseColorTexture, so an export looks like the view.
enum class PaperTexture { Plain, Grain, Image };

struct PaperLook {
    std::array<float, 3> color = kPaperColor; // sRGB, 0..1
    PaperTexture texture = PaperTexture::Plain;
    QImage image;      // PaperTexture::Image: the picked picture, as loadPaperImage left it
    QString imagePath; // where it came from, for menus, messages and settings
};

// The built-in paper grain: faint cloudy formation and fibres along the sheet's length,
// around 0.95 grey so it shades the colour rather than replacing it. The same pixels on
// every call and machine (integer hashing only), made once.
QImage paperGrainImage();

// The texture to draw for `look`: null for Plain.
QImage paperTextureImage(const PaperLook& look);

// The longest side a picked image keeps; larger ones are scaled down (a sheet's
// texture needs no more, and every GL, software ones included, takes this size).
inline constexpr int kMaxTextureSide = 2048;

// Reads an image for the paper (PNG, JPEG, ... whatever Qt reads), scaled to at most
// kMaxTextureSide. False and a message for an unreadable or empty file.
bool loadPaperImage(const QString& path, QImage* image, QString* error);

// "#rrggbb" (or an SVG colour name) to a colour; nullopt and a message otherwise.
std::optional<std::array<float, 3>> paperColorFromText(const QString& text, QString* error);
QString paperColorText(const std::array<float, 3>& color);

// "plain", "grain" or an image file's path: the texture part of a look (the colour kept).
bool setPaperTextureFromText(const QString& text, PaperLook* look, QString* error);
// The same text for a look's texture (its picture's path for an image).
QString paperTextureText(const PaperLook& look);

// The look as the mesh writers take it: the colour and the texture as PNG bytes.
SurfaceLook surfaceLook(const PaperLook& look);

} // namespace pf
