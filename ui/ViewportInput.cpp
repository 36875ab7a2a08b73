#include "ViewportInput.h"

#include "Picking.h"
#include "SimulationThread.h"
#include "Viewport.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace pf {

ViewportInput::ViewportInput(Viewport* viewport, SimulationThread* simulation, QObject* parent)
    : QObject(parent), viewport_(viewport), sim_(simulation) {
    viewport_->installEventFilter(this);
}

void ViewportInput::setToolRadius(double radius) {
    toolRadius_ = radius;
    sim_->setTool(toolTarget_, toolRadius_, true, toolPressed_);
}

void ViewportInput::fitCamera() {
    auto snap = viewport_->snapshot();
    if (!snap || snap->x.empty()) return;
    OrbitCamera c = viewport_->camera();
    c.fitPoints(snap->x,
                double(std::max(1, viewport_->width())) / std::max(1, viewport_->height()));
    viewport_->setCamera(c);
}

void ViewportInput::setView(const char* name) {
    OrbitCamera c = namedView(name).value();
    const OrbitCamera& now = viewport_->camera();
    c.target = now.target;
    c.distance = now.distance;
    viewport_->setCamera(c);
}

void ViewportInput::pointTool(const QPoint& pixel, bool pressed) {
    auto snap = viewport_->snapshot();
    if (!snap) return;
    const OrbitCamera::Ray ray = viewport_->camera().rayThroughPixel(
        pixel.x() + 0.5, pixel.y() + 0.5, viewport_->width(), viewport_->height());
    const auto hit = pickSheet(*snap, ray);
    if (!hit) return;
    toolTarget_ = toolCenter(*hit, toolRadius_, pressed ? kPushDepth * toolRadius_ : 0.0);
    const bool began = pressed && !toolPressed_;
    toolPressed_ = pressed;
    sim_->setTool(toolTarget_, toolRadius_, true, pressed);
    if (began) emit strokeBegan();
}

void ViewportInput::hideTool() {
    toolPressed_ = false;
    sim_->setTool(toolTarget_, toolRadius_, false, false);
}

bool ViewportInput::orbitPanOrZoom(QEvent* event) {
    OrbitCamera c = viewport_->camera();
    if (event->type() == QEvent::Wheel) {
        c.zoom(std::pow(0.9, static_cast<QWheelEvent*>(event)->angleDelta().y() / 120.0));
    } else if (event->type() == QEvent::KeyPress) {
        switch (static_cast<QKeyEvent*>(event)->key()) {
        case Qt::Key_Left:
            c.orbit(-5, 0);
            break;
        case Qt::Key_Right:
            c.orbit(5, 0);
            break;
        case Qt::Key_Up:
            c.orbit(0, 5);
            break;
        case Qt::Key_Down:
            c.orbit(0, -5);
            break;
        case Qt::Key_Plus:
        case Qt::Key_Equal:
            c.zoom(0.9);
            break;
        case Qt::Key_Minus:
            c.zoom(1.0 / 0.9);
            break;
        default:
            return false;
        }
    } else {
        return false;
    }
    viewport_->setCamera(c);
    return true;
}

bool ViewportInput::eventFilter(QObject* watched, QEvent* event) {
    if (watched != viewport_) return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseMove:
    case QEvent::MouseButtonRelease: {
        auto* e = static_cast<QMouseEvent*>(event);
        const QPoint pos = e->position().toPoint();
        const QPoint delta = pos - lastMouse_;
        lastMouse_ = pos;
        const bool move = event->type() == QEvent::MouseMove;
        const bool shift = e->modifiers() & Qt::ShiftModifier;
        if (move && (e->buttons() & Qt::RightButton) && !shift) {
            OrbitCamera c = viewport_->camera();
            c.orbit(-0.4 * delta.x(), 0.4 * delta.y());
            viewport_->setCamera(c);
            return true;
        }
        if (move &&
            ((e->buttons() & Qt::MiddleButton) || ((e->buttons() & Qt::RightButton) && shift))) {
            OrbitCamera c = viewport_->camera();
            c.pan(-double(delta.x()) / viewport_->height(),
                  double(delta.y()) / viewport_->height());
            viewport_->setCamera(c);
            return true;
        }
        pointTool(pos, e->buttons() & Qt::LeftButton);
        return true;
    }
    case QEvent::Wheel: {
        auto* e = static_cast<QWheelEvent*>(event);
        if (!(e->modifiers() & Qt::ControlModifier)) return orbitPanOrZoom(event);
        const double notches = e->angleDelta().y() / 120.0;
        setToolRadius(std::clamp(toolRadius_ * std::pow(1.1, notches), 0.01, 0.10));
        emit toolRadiusChanged(toolRadius_);
        return true;
    }
    case QEvent::Leave:
        hideTool();
        return false;
    case QEvent::KeyPress:
        return orbitPanOrZoom(event);
    default:
        return false;
    }
}

} // namespace pf
