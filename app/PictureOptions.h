#pragma once

#include "Camera.h"
#include "RenderOptions.h"
#include "SheetSnapshot.h"

#include <QCommandLineParser>

namespace pf::cli {

// The options that say what a picture looks like, shared by `render` and `replay`:
// --subdiv, --size, --view, --camera, --overlay, --no-legend, and the look's options.
void addPictureOptions(QCommandLineParser& parser);

struct PictureSetup {
    int width = 1280, height = 720;
    RenderOptions options;
    QStringList lookInputs; // a texture file the picture reads, which no output may replace
};
// Throws UsageError, naming the option, for a bad value.
PictureSetup pictureFromOptions(const QCommandLineParser& parser);

// Camera framing the sheet: the named view (or explicit angles) around the
// snapshot's bounding sphere. Throws UsageError for a bad --view or --camera.
OrbitCamera frameCamera(const SheetSnapshot& snap, const QCommandLineParser& parser, double aspect);

} // namespace pf::cli
