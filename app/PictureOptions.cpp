#include "PictureOptions.h"

#include "CommandLine.h"
#include "LookOptions.h"
#include "OffscreenRenderer.h"

#include <cmath>

namespace pf::cli {

void addPictureOptions(QCommandLineParser& parser) {
    parser.addOptions({
        {QStringLiteral("subdiv"), QStringLiteral("Subdivision level 0-4 (default 3)."),
         QStringLiteral("level")},
        {QStringLiteral("size"), QStringLiteral("Image size WxH (default 1280x720)."),
         QStringLiteral("WxH")},
        {QStringLiteral("view"), QStringLiteral("Named view: top, front, iso (default iso)."),
         QStringLiteral("name"), QStringLiteral("iso")},
        {QStringLiteral("camera"),
         QStringLiteral(
             "Explicit camera: yaw,pitch,distance (degrees, degrees, metres) around the sheet; "
             "a pitch that would put the eye under the desk is raised above it."),
         QStringLiteral("y,p,d")},
        {QStringLiteral("overlay"),
         QStringLiteral("Overlays, comma-separated: %1.").arg(overlayNames()),
         QStringLiteral("list")},
        {QStringLiteral("no-legend"), QStringLiteral("Leave the overlay legend out.")},
        {QStringLiteral("no-creases"),
         QStringLiteral("Draw the paper without its creases' fine lines (the surface alone).")},
    });
    addLookOptions(parser);
}

PictureSetup pictureFromOptions(const QCommandLineParser& parser) {
    // --camera sets all that --view names (yaw, pitch, distance): --view was dropped.
    if (parser.isSet(QStringLiteral("view")) && parser.isSet(QStringLiteral("camera")))
        throw UsageError{QStringLiteral("--view and --camera exclude each other (--camera sets "
                                        "the whole view)")};
    refuseWithout(parser, {"no-legend"}, "overlay");
    PictureSetup p;
    if (parser.isSet(QStringLiteral("size"))) {
        const QStringList wh = parser.value(QStringLiteral("size")).split(QLatin1Char('x'));
        bool okW = false, okH = false;
        if (wh.size() == 2) {
            p.width = wh[0].toInt(&okW);
            p.height = wh[1].toInt(&okH);
        }
        if (!okW || !okH || !OffscreenRenderer::sizeAllowed(p.width, p.height))
            throw UsageError{
                QStringLiteral("--size: expected WxH with each side %1-%2, e.g. 1920x1080")
                    .arg(OffscreenRenderer::kMinSize)
                    .arg(OffscreenRenderer::kMaxSize)};
    }
    p.options.subdivision =
        static_cast<int>(integerOption(parser, QStringLiteral("subdiv"), 0, 4).value_or(3));
    p.options.legend = !parser.isSet(QStringLiteral("no-legend"));
    p.options.creases = !parser.isSet(QStringLiteral("no-creases"));
    p.options.look = lookFromOptions(parser, &p.lookInputs);
    if (parser.isSet(QStringLiteral("overlay"))) {
        QString error;
        const auto bits = overlaysFromNames(parser.value(QStringLiteral("overlay")), &error);
        if (!bits) throw UsageError{QStringLiteral("--overlay: ") + error};
        p.options.overlays = *bits;
    }
    return p;
}

OrbitCamera frameCamera(const SheetSnapshot& snap, const QCommandLineParser& parser,
                        double aspect) {
    const QString viewName = parser.value(QStringLiteral("view"));
    std::optional<OrbitCamera> named = namedView(viewName.toStdString());
    if (!named)
        throw UsageError{
            QStringLiteral("--view: unknown view '%1' (known: top, front, iso)").arg(viewName)};
    OrbitCamera camera = *named;
    camera.fitPoints(snap.x, aspect);
    if (parser.isSet(QStringLiteral("camera"))) {
        const QStringList parts = parser.value(QStringLiteral("camera")).split(QLatin1Char(','));
        bool ok[3] = {false, false, false};
        if (parts.size() == 3) {
            camera.yaw = parts[0].toDouble(&ok[0]);
            camera.pitch = parts[1].toDouble(&ok[1]);
            camera.distance = parts[2].toDouble(&ok[2]);
        }
        // Written so that NaN fails every comparison and is refused.
        const bool inRange = ok[0] && ok[1] && ok[2] && std::abs(camera.yaw) <= 360.0 &&
                             std::abs(camera.pitch) <= 89.9 && camera.distance >= 0.01 &&
                             camera.distance <= 20.0;
        if (!inRange)
            throw UsageError{QStringLiteral("--camera: expected yaw,pitch,distance in degrees "
                                            "(|yaw| ≤ 360), degrees (|pitch| ≤ 89.9) and metres "
                                            "(0.01-20)")};
    }
    // Never from under the desk, which hides the paper (a pitch of -30° drew the desk's
    // underside and nothing else): the eye is kept above it as the editor's orbit keeps it.
    if (snap.groundEnabled) camera.keepAbove(snap.groundHeight);
    // A sheet whose points lie too far out renders as empty sky in single precision.
    if (!camera.target.allFinite() || camera.target.norm() > 1e3 ||
        !std::isfinite(camera.distance) || camera.distance > 1e3)
        throw UsageError{QStringLiteral("the sheet lies too far from the origin to render "
                                        "(more than 1 km)")};
    return camera;
}

} // namespace pf::cli
