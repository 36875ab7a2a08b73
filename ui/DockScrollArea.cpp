#include "DockScrollArea.h"

#include <QEvent>
#include <QScrollBar>

namespace pf {

DockScrollArea::DockScrollArea(QWidget* content, QWidget* parent) : QScrollArea(parent) {
    setWidget(content);
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
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

bool DockScrollArea::eventFilter(QObject* watched, QEvent* event) {
    const bool contentsChanged = watched == widget() && event->type() == QEvent::LayoutRequest;
    const bool barShownOrHidden = watched == verticalScrollBar() &&
                                  (event->type() == QEvent::Show || event->type() == QEvent::Hide);
    if (contentsChanged || barShownOrHidden) updateGeometry();
    if (contentsChanged) emit contentsResized();
    return QScrollArea::eventFilter(watched, event);
}

} // namespace pf
