#pragma once

#include "PaperLook.h"
#include "Types.h"

#include <QString>
#include <optional>

namespace pf {

// Overlays, each switchable. Colours follow the paper's Fig. 4 where it has them:
// breakable springs blue, auxiliary (crease) springs red.
enum Overlay : unsigned {
    OverlaySpringKinds = 1u << 0,      // structural blue, crease red, hinge green
    OverlayBreakProbability = 1u << 1, // Eq. 10 per edge, heat colours
    OverlayStrain = 1u << 2,           // |l/l0 - 1| on the surface, heat colours
    OverlayRecentBreaks = 1u << 3,     // edges broken in the last second
    OverlayWireframe = 1u << 4,        // the simulation mesh over the subdivided surface
};

struct RenderOptions {
    int subdivision = 3;
    // σ of §4.3: how sharply the subdivided surface creases (0 keeps it flat between
    // vertices). A look, not physics: the simulation never sees it.
    double sigma = 1.0;
    unsigned overlays = 0;
    bool ground = true;
    bool sphere = true;
    // Where a hovering tool is drawn, when the view has placed it on this very picture:
    // the simulation's sphere was placed on the picture before, and a sheet swinging
    // under a still cursor went through it.
    std::optional<Vec3> hoverCenter;
    bool legend = true;
    // Markers on pinned vertices (the editor's pins; a headless render leaves them out).
    bool pins = false;
    // The model's creases (its broken edges) drawn as fine lines a shade darker than the
    // paper, as the damaged fibres of a real crease show. Pulled flat again, crumpled
    // paper's surface has no fold left to shade, and a sheet crumpled ten times was a
    // clean white rectangle.
    bool creases = true;
    // Share of the facet normal in the shading: 0 smooth, 1 faceted.
    double facet = 0.35;
    // Heat-map ranges (values at the top of the legend).
    double strainRange = 0.05;
    double probabilityRange = 0.05;
    PaperLook look;
};

// Parses "springs,probability,strain,breaks,wireframe" (or "none"); nullopt and a
// message naming the unknown word otherwise.
std::optional<unsigned> overlaysFromNames(const QString& names, QString* error);
QString overlayNames();

} // namespace pf
