#include "DockScrollArea.h"

#include <QEvent>
#include <QScrollBar>

namespace pf {

DockScrollArea::DockScrollArea(QWidget* content, QWidget* parent) : QScrollArea(parent) {
    setWidget(content);
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // A click in the dock that lands on no control leaves the keys where they were (the
    // view's shortcuts), not with the scroll area; the wheel still scrolls it.
    setFocusPolicy(Qt::NoFocus);
    contentsHint_ = content->sizeHint();
    content->installEventFilter(this); // its size hints change with the language
    verticalScrollBar()->installEventFilter(this);
}

// Room for the scroll bar only while it shows: a tall enough window lays the docks out
// as before (the view's width, and so what a stroke in it does, stays the same).
int DockScrollArea::scrollBarWidth() const {
    return verticalScrollBar()->isVisibleTo(this) ? verticalScrollBar()->sizeHint().width() : 0;
}

QSize DockScrollArea::sizeHint() const {
    return widget()->sizeHint() + QSize(scrollBarWidth(), 0);
}

// As wide as the contents (no horizontal scrolling, labels are never cut), and a few
// lines high.
QSize DockScrollArea::minimumSizeHint() const {
    return {widget()->minimumSizeHint().width() + scrollBarWidth(), 3 * fontMetrics().height()};
}

// The Solver panel's readouts change their text at every frame, and each change asks
// for a new layout: only a change of the contents' size hint is passed on, and only one
// of its height as contentsResized (passed on at every frame, the docks were laid out
// again 60 times a second and a dragged splitter sprang back).
bool DockScrollArea::eventFilter(QObject* watched, QEvent* event) {
    if (watched == widget() && event->type() == QEvent::LayoutRequest) {
        const QSize hint = widget()->sizeHint();
        if (hint != contentsHint_) {
            const bool heightChanged = hint.height() != contentsHint_.height();
            contentsHint_ = hint;
            updateGeometry();
            if (heightChanged) emit contentsResized();
        }
    }
    if (watched == verticalScrollBar() &&
        (event->type() == QEvent::Show || event->type() == QEvent::Hide))
        updateGeometry();
    return QScrollArea::eventFilter(watched, event);
}

} // namespace pf
