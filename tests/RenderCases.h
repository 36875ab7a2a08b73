#pragma once

#include "Camera.h"
#include "RenderOptions.h"
#include "SheetSnapshot.h"

#include <QString>
#include <vector>

namespace pf::test {

// One picture the rendering tests know: a scene run for some steps, seen from a view.
struct RenderCase {
    QString name;
    const char* scene;
    int steps;
    const char* view; // named view, or "" for the explicit angles below
    double yaw, pitch, distance;
    double sigma;
    unsigned overlays;
    int subdivision;
    int resolution = 0; // 0: the scene's own
    double bumps = 0.0; // amplitude (m) of a fixed bump field added after stepping
    PaperTexture texture = PaperTexture::Plain;
};

const std::vector<RenderCase>& renderCases();

SheetSnapshot snapshotFor(const RenderCase& c);
// The named view (or explicit angles) fitted to the snapshot.
OrbitCamera cameraFor(const RenderCase& c, const SheetSnapshot& snap, double aspect);
RenderOptions optionsFor(const RenderCase& c);

} // namespace pf::test
