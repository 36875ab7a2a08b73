#pragma once

#include "RenderOptions.h"
#include "SheetSnapshot.h"

#include <cstdint>
#include <vector>

namespace pf {

// Which subdivided surface a snapshot is drawn with: the snapshot and the options
// that shape the surface (the camera and the overlay lines do not).
struct SurfaceKey {
    std::uint64_t serial = 0;
    int subdivision = -1;
    double sigma = -1.0, strainRange = -1.0;
    bool strain = false;
    friend bool operator==(const SurfaceKey&, const SurfaceKey&) = default;
};

SurfaceKey surfaceKeyOf(const SheetSnapshot& snapshot, const RenderOptions& options);

// The subdivided surface of a snapshot as the renderer uploads it: interleaved
// position 3, normal 3, colour 4 (the strain heat map, or none), texture coordinate 2,
// and the triangles' indices. No GL: it is what a frame costs the CPU before GL
// (ui/README.md measures building it on the simulation thread instead, not kept).
struct DrawnSurface {
    static constexpr int kFloatsPerVertex = 12;
    SurfaceKey key;
    bool hasUvs = false;
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;
};

// Fills `out` (keeping its capacity unless it is more than twice what is needed).
void buildDrawnSurface(const SheetSnapshot& snapshot, const RenderOptions& options,
                       DrawnSurface& out);

// The options the editor draws a snapshot of `simulationTriangles` with: at most
// kInteractiveTriangles surface triangles, so that a crumpled sheet is drawn one level
// coarser rather than multiplying the frame time, and the software GL driver's memory
// (which keeps the largest recent frames) stays bounded.
inline constexpr std::size_t kInteractiveTriangles = 65536;
RenderOptions interactiveOptions(const RenderOptions& options, std::size_t simulationTriangles);

} // namespace pf
