#pragma once

#include "RenderOptions.h"

#include <QColor>
#include <QPainter>
#include <QRect>
#include <QString>
#include <vector>

namespace pf {

// What the legend says for the active overlays: a heat map's title and the text at the
// top of its bar, and a label beside each colour swatch. Numbers are written as the
// default QLocale writes them: the editor sets it to its translation's language, the
// command line to C (its texts are English).
struct LegendContent {
    struct Bar {
        QString title;
        QString top; // "≥ 0.05", "≥ 1%"
    };
    struct Swatch {
        QColor color;
        QString label;
    };
    std::vector<Bar> bars;
    std::vector<Swatch> swatches;
};
LegendContent legendContent(const RenderOptions& options);

// Keys for the active overlays, drawn in the lower-left corner of `area`: a colour
// bar with its range for each heat map, a swatch list for spring kinds. The editor
// draws it over its viewport, the headless path over the image.
void drawLegend(QPainter& painter, const QRect& area, const RenderOptions& options);

} // namespace pf
