#include "StatusReadout.h"

#include <QEvent>
#include <QLabel>
#include <QLocale>
#include <QStatusBar>

namespace pf {

StatusReadout::StatusReadout(QStatusBar* bar)
    : QObject(bar), bar_(bar), fps_(new QLabel(bar)), step_(new QLabel(bar)),
      counts_(new QLabel(bar)) {
    bar->addWidget(fps_);
    bar->addWidget(step_);
    counts_->setObjectName(QStringLiteral("sheetCounts"));
    step_->setObjectName(QStringLiteral("stepReadout"));
    bar->addPermanentWidget(counts_);
    connect(bar, &QStatusBar::messageChanged, this, &StatusReadout::makeRoomForTheMessage);
    bar->installEventFilter(this);
    clock_.start();
}

bool StatusReadout::eventFilter(QObject* watched, QEvent* event) {
    if (watched == bar_ && event->type() == QEvent::Resize) makeRoomForTheMessage();
    return QObject::eventFilter(watched, event);
}

// The status bar draws a message only left of its permanent widgets and cuts it off
// there: at 800 pixels "The fold opened 61° again…" lost its second half, which says
// what to do. The counts give way while such a message shows and come back when it
// goes; a message that does not fit even then can be read whole as the bar's tooltip.
void StatusReadout::makeRoomForTheMessage() {
    const QString message = bar_->currentMessage();
    bar_->setToolTip(message);
    // The margins QStatusBar keeps round the message (6 px before it, 2 px after), its
    // layout's spacing on each side of the spacer, and the size grip: about 34 px.
    constexpr int kMargins = 40;
    const int needed = bar_->fontMetrics().horizontalAdvance(message) + kMargins;
    const bool fits =
        message.isEmpty() || needed + counts_->sizeHint().width() <= bar_->contentsRect().width();
    counts_->setVisible(fits);
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
    // Nothing is drawn while nothing moves: "0 fps" beside a still sheet read as a frozen
    // editor.
    const bool idle = still_ && fpsValue_ == 0.0;
    fps_->setText(idle ? tr("– fps") : tr("%1 fps").arg(fpsValue_, 0, 'f', 0));
    fps_->setToolTip(idle ? tr("Nothing moves, so the view is not drawn again until something "
                               "changes.")
                          : QString());
}

void StatusReadout::show(const SimulationStatus& st) {
    still_ = !st.playing || st.settled || st.resting();
    updateFps();
    // A user could not tell a sheet lying still from one that only looked still.
    QString step = st.stepSeconds > 0.0 ? tr("step %1 µs").arg(st.stepSeconds * 1e6, 0, 'f', 0)
                   : st.resting()       ? QString() // asleep for less than a tick
                                        : tr("no step yet");
    // Paused, the toolbar's icon was the only sign, and a paused sheet could read "at rest".
    if (!st.playing)
        step = tr("%1 · paused").arg(step);
    else if (st.settled) // it read "0 fps step 1 µs", and a user could not tell it frozen
        step = step.isEmpty() ? tr("settled") : tr("%1 · settled").arg(step);
    else if (st.resting())
        step = step.isEmpty() ? tr("at rest") : tr("%1 · at rest").arg(step);
    // Behind real time, the paper falls and slides slower than paper does: say so, and
    // what helps.
    // (A sheet at rest keeps up whatever the last second's pace was: a user read
    // "at rest · 0.74× real time" for the second after a slow stroke.)
    const bool behind = st.playing && !st.resting() && !st.settled && st.pace < kBehindRealTime;
    if (behind) step = tr("%1 · %2× real time").arg(step, QLocale().toString(st.pace, 'f', 2));
    step_->setText(step);
    step_->setToolTip(behind ? tr("The computer cannot take the steps as fast as they happen: "
                                  "the sheet moves slower than in real time. Fewer steps per "
                                  "second (Solver dock), a smaller sheet or another integrator "
                                  "are faster.")
                             : QString());
    // The counts that can be one are said with their plural forms ("1 break", "2 breaks").
    counts_->setText(tr("%1 vertices · %2 springs · %3 (%4/s) · %5")
                         .arg(st.vertices)
                         .arg(st.springs)
                         .arg(tr("%n break(s)", nullptr, st.breaks))
                         .arg(st.breaksLastSecond)
                         .arg(tr("%n hinge(s)", nullptr, st.hinges)));
    // Behind real time the paper's second lasts longer on the clock: a user read "865
    // breaks (865/s)" at 0.03× real time as 865 in the last second he waited. Paused, it
    // is the paper's last second before the pause (the step readout says "paused"), and a
    // step taken by hand moves it on.
    counts_->setToolTip(tr("In brackets: the breaks in the last second of simulated time, "
                           "which lasts longer than a second on the clock while the sheet "
                           "runs behind real time"));
}

} // namespace pf
