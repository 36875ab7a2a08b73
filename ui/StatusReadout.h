#pragma once

#include "SimulationStatus.h"

#include <QElapsedTimer>
#include <QObject>

class QLabel;
class QStatusBar;

namespace pf {

// The status bar's live numbers: frames drawn per second, the cost of a step, and the
// sheet's size and damage.
class StatusReadout : public QObject {
    Q_OBJECT

  public:
    explicit StatusReadout(QStatusBar* bar);

    // Called once per frame drawn.
    void show(const SimulationStatus& status);

  private:
    QLabel *fps_, *step_, *counts_;
    QElapsedTimer clock_;
    int frames_ = 0;
    double fpsValue_ = 0.0;
};

} // namespace pf
