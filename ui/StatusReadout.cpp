#include "StatusReadout.h"

#include <QLabel>
#include <QStatusBar>

namespace pf {

StatusReadout::StatusReadout(QStatusBar* bar)
    : QObject(bar), fps_(new QLabel(bar)), step_(new QLabel(bar)), counts_(new QLabel(bar)) {
    bar->addWidget(fps_);
    bar->addWidget(step_);
    bar->addPermanentWidget(counts_);
    clock_.start();
}

void StatusReadout::frameDrawn() {
    ++frames_;
    updateFps();
}

void StatusReadout::updateFps() {
    if (clock_.elapsed() > 500) {
        fpsValue_ = 1000.0 * frames_ / clock_.restart();
        frames_ = 0;
    }
    fps_->setText(tr("%1 fps").arg(fpsValue_, 0, 'f', 0));
}

void StatusReadout::show(const SimulationStatus& st) {
    updateFps();
    // A user could not tell a sheet lying still from one that only looked still.
    const QString step = tr("step %1 µs").arg(st.stepSeconds * 1e6, 0, 'f', 0);
    step_->setText(st.resting() ? tr("%1 · at rest").arg(step) : step);
    // The counts that can be one are said with their plural forms ("1 break", "2 breaks").
    counts_->setText(tr("%1 vertices · %2 springs · %3 (%4/s) · %5")
                         .arg(st.vertices)
                         .arg(st.springs)
                         .arg(tr("%n break(s)", nullptr, st.breaks))
                         .arg(st.breaksLastSecond)
                         .arg(tr("%n hinge(s)", nullptr, st.hinges)));
}

} // namespace pf
