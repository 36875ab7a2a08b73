// clang-format off
// Viewport.h first: GlFunctions.h takes GL's types from glcorearb.h, which leaves out
// the GL 1.1 ones once <QOpenGLWindow> has brought in the system's gl.h.
#include "Viewport.h"
#include "ViewportWindow.h"
// clang-format on

#include <QCoreApplication>
#include <QMouseEvent>
#include <memory>

namespace pf {

ViewportWindow::ViewportWindow(Viewport* view) : view_(view) {
    setFormat(Viewport::viewFormat());
    setFlag(Qt::WindowDoesNotAcceptFocus);
    // Announced once the frame is on screen, not from inside paintGL: a receiver may
    // close the window, and the context must outlive the paint.
    connect(this, &QOpenGLWindow::frameSwapped, view, &Viewport::frameDrawn);
}

void ViewportWindow::initializeGL() {
    view_->initializeGl(context());
}

void ViewportWindow::paintGL() {
    view_->paintGl(defaultFramebufferObject());
}

bool ViewportWindow::event(QEvent* event) {
    switch (event->type()) {
    case QEvent::UpdateRequest:
        // An update asked for before the window showed, or while it is being closed,
        // comes when there is no context: QOpenGLWindow would paint through a null one.
        if (!context() || !isExposed()) return true;
        return QOpenGLWindow::event(event);
    case QEvent::MouseMove:
        // A widget sees moves without a button only when it tracks the mouse.
        if (static_cast<QMouseEvent*>(event)->buttons() == Qt::NoButton &&
            !view_->hasMouseTracking())
            return true;
        [[fallthrough]];
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::Wheel:
    case QEvent::Enter:
    case QEvent::Leave: {
        // The window fills the viewport from its corner, so its coordinates are the
        // viewport's: the same event, delivered to the widget.
        if (event->type() == QEvent::MouseButtonPress) view_->setFocus(Qt::MouseFocusReason);
        const std::unique_ptr<QEvent> copy(event->clone());
        QCoreApplication::sendEvent(view_, copy.get());
        return true;
    }
    default:
        return QOpenGLWindow::event(event);
    }
}

} // namespace pf
