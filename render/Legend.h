#pragma once

#include "RenderOptions.h"

#include <QPainter>
#include <QRect>

namespace pf {

// Keys for the active overlays, drawn in the lower-left corner of `area`: a colour
// bar with its range for each heat map, a swatch list for spring kinds. The editor
// draws it over its viewport, the headless path over the image.
void drawLegend(QPainter& painter, const QRect& area, const RenderOptions& options);

} // namespace pf
