#pragma once

#include "Types.h"

#include <QObject>
#include <QPoint>

namespace pf {

class SimulationThread;
class Viewport;

// Turns the viewport's mouse, wheel and keys into camera moves and tool commands:
// right drag orbits, middle (or Shift + right) drag pans, the wheel zooms, Ctrl + wheel
// sizes the tool, the left button pushes the tool into the sheet where the cursor's ray
// meets it, arrows and +/- orbit and zoom. Installed as the viewport's event filter.
class ViewportInput : public QObject {
    Q_OBJECT

  public:
    ViewportInput(Viewport* viewport, SimulationThread* simulation, QObject* parent = nullptr);

    // How far a pressed tool reaches into the paper, as a share of its radius.
    static constexpr double kPushDepth = 0.6;
    static constexpr double kDefaultToolRadius = 0.03; // m

    double toolRadius() const { return toolRadius_; }
    void setToolRadius(double radius);
    Vec3 toolTarget() const { return toolTarget_; }
    bool toolPressed() const { return toolPressed_; }

    // Fits the sheet into view, keeping the direction; sets a named view (top, front,
    // iso), keeping the target and distance.
    void fitCamera();
    void setView(const char* name);

  signals:
    void toolRadiusChanged(double radius); // by Ctrl + wheel
    void strokeBegan();                    // the left button went down over the sheet

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void pointTool(const QPoint& pixel, bool pressed);
    void hideTool();
    bool orbitPanOrZoom(QEvent* event);

    Viewport* viewport_;
    SimulationThread* sim_;
    double toolRadius_ = kDefaultToolRadius;
    Vec3 toolTarget_ = Vec3::Zero();
    bool toolPressed_ = false;
    QPoint lastMouse_;
};

} // namespace pf
