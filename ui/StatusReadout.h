#pragma once

#include "SimulationStatus.h"

#include <QElapsedTimer>
#include <QObject>

class QLabel;
class QStatusBar;

namespace pf {

// The status bar's live numbers: frames drawn per second, the cost of a step, and the
// sheet's size and damage. A message that needs their room (why a fold was refused,
// that a fold opened again) gets it while it shows.
class StatusReadout : public QObject {
    Q_OBJECT

  public:
    // Below this pace (simulated seconds per second) the status bar says the sheet runs
    // behind real time: the pacer's own rounding and a late tick stay above it.
    static constexpr double kBehindRealTime = 0.9;

    explicit StatusReadout(QStatusBar* bar);

    // The simulation's numbers, once per snapshot published.
    void show(const SimulationStatus& status);
    // Called once per frame the view draws: a snapshot that draws the same picture as
    // the one shown is not drawn again, so a still sheet reads "– fps", not "0 fps".
    void frameDrawn();

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void updateFps();
    void makeRoomForTheMessage();

    QStatusBar* bar_;
    QLabel *fps_, *step_, *counts_;
    QElapsedTimer clock_;
    int frames_ = 0;
    double fpsValue_ = 0.0;
    bool still_ = false; // the sheet rests, is settled or paused: nothing needs drawing
};

} // namespace pf
