#pragma once

#include "Camera.h"
#include "Picking.h"
#include "Types.h"

#include <QObject>
#include <QPoint>
#include <optional>

namespace pf {

class SimulationThread;
class Viewport;

// Turns the viewport's mouse, wheel and keys into camera moves and tool commands:
// right drag orbits, middle (or Shift + right) drag pans, the wheel zooms, Ctrl + wheel
// sizes the tool, arrows and +/- orbit and zoom. The left button uses the chosen tool
// where the cursor's ray meets the sheet: Push presses the sphere into it, Grab picks
// the point up and drags it in the plane facing the view (the wheel moves it nearer or
// further meanwhile), Pin toggles the pins around the point, Fold draws the line a fold
// is made along (from press to release, across the paper). Installed as the viewport's
// event filter.
class ViewportInput : public QObject {
    Q_OBJECT

  public:
    ViewportInput(Viewport* viewport, SimulationThread* simulation, QObject* parent = nullptr);

    enum class Tool { Push, Grab, Pin, Fold };
    Tool tool() const { return tool_; }
    // The push tool's sphere under the cursor again, where the cursor lies over the view
    // without having moved: after a modal dialog the sphere stayed hidden (the view saw
    // the cursor leave) until the mouse moved.
    void showToolUnderCursor();
    // The hovering sphere put back under the pixel the cursor last pointed it from, after
    // the view or the sheet under it changed without the mouse moving: after Open and
    // Reset it hung where the old framing had put it until the mouse moved; paper that
    // sprang back after a push rose through it, and a sheet that fell left it in the air.
    void toolFollowsTheView();
    void setTool(Tool tool);
    // The sheet let go of a held grab (an undo or redo): the hand holds nothing until the
    // next press.
    void letGo();

    // How far a pressed tool reaches into the paper, as a share of its radius.
    static constexpr double kDefaultPushDepth = 0.6;
    double pushDepth() const { return pushDepth_; }
    void setPushDepth(double shareOfRadius) { pushDepth_ = shareOfRadius; }
    static constexpr double kDefaultToolRadius = 0.03; // m
    // A pin click toggles the vertices within this share of the tool's radius.
    static constexpr double kPinShare = 0.5;
    // A pin click off the paper frees a pin whose mark it is this near (pixels).
    static constexpr int kPinMarkPixels = 4;
    // How far one wheel notch moves a grabbed point toward or away from the eye.
    static constexpr double kGrabWheelStep = 0.01; // m

    double toolRadius() const { return toolRadius_; }
    void setToolRadius(double radius);
    Vec3 toolTarget() const { return toolTarget_; }
    bool toolPressed() const { return toolPressed_ || grabbing_; }

    // Fits the sheet into view, keeping the direction; sets a named view (top, front,
    // iso), keeping the target and distance.
    void fitCamera();
    // Fits a sheet that New or Open brought, seen from the direction the editor starts
    // with: the old sheet's orbit (a user's view from straight above) stood over it.
    void frameNewSheet();
    void setView(const char* name);

  signals:
    void toolRadiusChanged(double radius); // by Ctrl + wheel
    void strokeBegan();                    // the left button went down over the sheet
    void acted();                          // any press, wheel or key the view handled
    // A fold line was drawn from `from` (on the paper or the desk) to `to` (in the plane
    // facing the way the paper or desk did there).
    void foldDrawn(const pf::Vec3& from, const pf::Vec3& to);
    // The left button took hold of the paper with Push or Grab, or let it go
    // (toolPressed changed).
    void holdChanged(bool holding);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    // Mouse, wheel and keys, before holdChanged is worked out.
    bool handle(QEvent* event);
    void sayIfHoldChanged(bool wasHolding);
    void pointTool(const QPoint& pixel, bool pressed);
    // The push tool's sphere to `center`, pointed from `pixel`.
    void placeTool(const QPoint& pixel, const Vec3& center, bool pressed);
    // Where the push tool's centre goes for the cursor at `pixel`; nothing under it, none.
    std::optional<Vec3> toolCenterAt(const QPoint& pixel, bool pressed) const;
    // Grab and Pin: the left button at `pixel` (pressed, moved with it held, released).
    void useGrab(const QPoint& pixel, bool held, bool press);
    void usePin(const QPoint& pixel, bool pressed);
    void useFold(const QPoint& pixel, bool held, bool press);
    std::optional<PickHit> pick(const QPoint& pixel) const;
    OrbitCamera::Ray rayAt(const QPoint& pixel) const;
    Vec3 facing() const; // the view's direction, from the eye
    void hideTool();
    bool orbitPanOrZoom(QEvent* event);
    // Shows the view from `camera`, kept above the desk (OrbitCamera::keepAbove): an
    // orbit, a pan or a zoom stops there.
    void look(OrbitCamera camera);

    Viewport* viewport_;
    SimulationThread* sim_;
    double toolRadius_ = kDefaultToolRadius;
    double pushDepth_ = kDefaultPushDepth;
    Vec3 toolTarget_ = Vec3::Zero();
    bool toolPressed_ = false;
    bool toolShown_ = true;           // a scene may start with the sphere shown
    std::optional<QPoint> toolPixel_; // where the cursor last pointed the shown tool
    Tool tool_ = Tool::Push;
    bool grabbing_ = false;
    Vec3 grabPoint_ = Vec3::Zero(); // the plane the grab moves in passes through it
    QPoint grabPixel_;
    bool pinHeld_ = false;
    bool foldDrawing_ = false;
    Vec3 foldFrom_ = Vec3::Zero(), foldNormal_ = Vec3::UnitY();
    QPoint foldPixel_;
    QPoint lastMouse_;
};

} // namespace pf
