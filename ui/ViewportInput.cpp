#include "ViewportInput.h"

#include "Picking.h"
#include "SimulationThread.h"
#include "Viewport.h"

#include <QApplication>
#include <QCursor>
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
    if (tool_ == Tool::Push) sim_->setTool(toolTarget_, toolRadius_, true, toolPressed_);
}

void ViewportInput::setTool(Tool tool) {
    if (tool == tool_) return;
    const bool wasHolding = toolPressed();
    if (grabbing_) useGrab(grabPixel_, false, false); // let go of what is held
    foldDrawing_ = false;
    viewport_->setFoldLine({});
    tool_ = tool;
    hideTool();
    switch (tool) {
    case Tool::Push:
        viewport_->unsetCursor();
        break;
    case Tool::Grab:
        viewport_->setCursor(Qt::OpenHandCursor);
        break;
    case Tool::Pin:
    case Tool::Fold:
        viewport_->setCursor(Qt::CrossCursor);
        break;
    }
    sayIfHoldChanged(wasHolding);
}

void ViewportInput::sayIfHoldChanged(bool wasHolding) {
    if (toolPressed() != wasHolding) emit holdChanged(toolPressed());
}

OrbitCamera::Ray ViewportInput::rayAt(const QPoint& pixel) const {
    return viewport_->camera().rayThroughPixel(pixel.x() + 0.5, pixel.y() + 0.5, viewport_->width(),
                                               viewport_->height());
}

Vec3 ViewportInput::facing() const {
    const OrbitCamera& c = viewport_->camera();
    return (c.target - c.eye()).normalized();
}

std::optional<PickHit> ViewportInput::pick(const QPoint& pixel) const {
    auto snap = viewport_->snapshot();
    if (!snap) return std::nullopt;
    return pickSheet(*snap, rayAt(pixel));
}

void ViewportInput::fitCamera() {
    auto snap = viewport_->snapshot();
    if (!snap || snap->x.empty()) return;
    OrbitCamera c = viewport_->camera();
    // The sheet and the desk under it: a sheet framed in the air (New ▸ drop) fell out of
    // the bottom of the view. Each point's place on the desk is framed with it.
    std::vector<Vec3> framed = snap->x;
    if (snap->groundEnabled)
        for (const Vec3& p : snap->x) framed.push_back(Vec3(p.x(), snap->groundHeight, p.z()));
    c.fitPoints(framed, double(std::max(1, viewport_->width())) / std::max(1, viewport_->height()));
    viewport_->setCamera(c);
    toolFollowsTheView();
}

void ViewportInput::frameNewSheet() {
    const OrbitCamera start;
    OrbitCamera c = viewport_->camera();
    c.yaw = start.yaw;
    c.pitch = start.pitch;
    viewport_->setCamera(c);
    fitCamera();
}

void ViewportInput::setView(const char* name) {
    OrbitCamera c = namedView(name).value();
    const OrbitCamera& now = viewport_->camera();
    c.target = now.target;
    c.distance = now.distance;
    viewport_->setCamera(c);
    toolFollowsTheView();
}

std::optional<Vec3> ViewportInput::toolCenterAt(const QPoint& pixel, bool pressed) const {
    const SheetSnapshot* snap = viewport_->snapshot();
    if (!snap) return std::nullopt;
    const OrbitCamera::Ray ray = rayAt(pixel);
    const auto hit = pickSheet(*snap, ray);
    if (!hit) return std::nullopt;
    // Where the desk has faded into the background a sphere resting on it looks afloat.
    const OrbitCamera& camera = viewport_->camera();
    const Vec3 fromTarget = hit->point - camera.target;
    if (!pressed && !hit->onSheet &&
        Vec2(fromTarget.x(), fromTarget.z()).norm() > camera.deskShown())
        return std::nullopt;
    // Pressed, it reaches into the paper; hovering, it touches none.
    return pressed ? toolCenter(*hit, toolRadius_, pushDepth_ * toolRadius_)
                   : restingToolCenter(*snap, ray, *hit, toolRadius_);
}

void ViewportInput::pointTool(const QPoint& pixel, bool pressed) {
    if (const auto center = toolCenterAt(pixel, pressed))
        placeTool(pixel, *center, pressed);
    else if (!pressed)
        hideTool(); // over the sky or the faded desk: it hung there, afloat
}

void ViewportInput::placeTool(const QPoint& pixel, const Vec3& center, bool pressed) {
    toolTarget_ = center;
    viewport_->setHoverCenter(pressed ? std::nullopt : std::optional(center));
    const bool began = pressed && !toolPressed_;
    toolPressed_ = pressed;
    toolShown_ = true;
    toolPixel_ = pixel;
    sim_->setTool(toolTarget_, toolRadius_, true, pressed);
    if (began) emit strokeBegan();
}

void ViewportInput::letGo() {
    if (!grabbing_) return;
    const bool wasHolding = toolPressed();
    grabbing_ = false;
    viewport_->setCursor(Qt::OpenHandCursor);
    sayIfHoldChanged(wasHolding);
}

void ViewportInput::useGrab(const QPoint& pixel, bool held, bool press) {
    if (!grabbing_) {
        if (!held || !press) return;
        const auto hit = pick(pixel);
        if (!hit || !hit->onSheet) return;
        grabbing_ = true;
        grabPoint_ = hit->point;
        grabPixel_ = pixel;
        viewport_->setCursor(Qt::ClosedHandCursor);
        sim_->grab(grabPoint_, true, true);
        emit strokeBegan();
        return;
    }
    // The point under the cursor in the plane through the grabbed point that faces the
    // view: dragging moves it across the screen at the depth it was picked up at.
    grabPixel_ = pixel;
    const OrbitCamera::Ray ray = rayAt(pixel);
    const Vec3 ahead = facing();
    const double along = ray.direction.dot(ahead);
    Vec3 target = grabPoint_;
    if (std::abs(along) > 1e-9)
        target = ray.origin + ray.direction * ((grabPoint_ - ray.origin).dot(ahead) / along);
    sim_->grab(target, held, false);
    if (held) return;
    grabbing_ = false;
    viewport_->setCursor(Qt::OpenHandCursor);
}

void ViewportInput::usePin(const QPoint& pixel, bool pressed) {
    const bool click = pressed && !pinHeld_;
    pinHeld_ = pressed;
    if (!click) return;
    const auto hit = pick(pixel);
    std::optional<Vec3> at;
    if (hit && hit->onSheet) {
        at = hit->point;
    } else if (const SheetSnapshot* snap = viewport_->snapshot()) {
        // Off the paper, on a pin's mark: the pin.
        const double spread = std::acos(std::clamp(
            rayAt(pixel).direction.dot(rayAt(pixel + QPoint(kPinMarkPixels, 0)).direction), -1.0,
            1.0));
        if (const auto pin = pinMarkOnRay(*snap, rayAt(pixel), spread))
            at = snap->x[static_cast<std::size_t>(*pin)];
    }
    if (!at) return;
    sim_->pin(*at, kPinShare * toolRadius_);
    emit strokeBegan();
}

void ViewportInput::useFold(const QPoint& pixel, bool held, bool press) {
    if (!foldDrawing_) {
        if (!held || !press) return;
        // The line may start off the paper, on the desk, as a ruler laid across it does.
        const auto hit = pick(pixel);
        if (!hit) return;
        foldDrawing_ = true;
        foldFrom_ = hit->point;
        foldNormal_ = hit->normal;
        foldPixel_ = pixel;
        viewport_->setFoldLine(QLine(pixel, pixel));
        emit strokeBegan();
        return;
    }
    viewport_->setFoldLine(QLine(foldPixel_, pixel));
    if (held) return;
    foldDrawing_ = false;
    viewport_->setFoldLine({});
    // Where the cursor's ray meets the paper's plane at the line's start: the line may
    // end beyond the sheet's edge, as a ruler does.
    const OrbitCamera::Ray ray = rayAt(pixel);
    const double along = ray.direction.dot(foldNormal_);
    if (std::abs(along) < 1e-9) return; // seen edge-on
    const double t = (foldFrom_ - ray.origin).dot(foldNormal_) / along;
    if (t <= 0.0) return;
    emit foldDrawn(foldFrom_, ray.origin + t * ray.direction);
}

void ViewportInput::showToolUnderCursor() {
    if (tool_ != Tool::Push || toolShown_ || !viewport_->isVisible()) return;
    // (QCursor::pos may be stale where the platform does not say where the cursor is,
    // as on Wayland; the next move corrects it.)
    const QPoint global = QCursor::pos();
    const QPoint at = viewport_->mapFromGlobal(global);
    if (!viewport_->rect().contains(at)) return;
    // Not under a floating dock or another window that covers the view there.
    const QWidget* under = QApplication::widgetAt(global);
    if (under && under != viewport_ && !viewport_->isAncestorOf(under)) return;
    pointTool(at, false);
}

void ViewportInput::toolFollowsTheView() {
    if (tool_ != Tool::Push || !toolShown_ || toolPressed_ || !toolPixel_) return;
    const auto center = toolCenterAt(*toolPixel_, false);
    if (!center) {
        if (viewport_->snapshot()) hideTool(); // the view turned the cursor to the sky
        return;
    }
    // A tenth of a millimetre is no move anyone sees, and each move is a command the
    // session records: a sheet at rest, or one moving elsewhere, leaves the tool be.
    if ((*center - toolTarget_).norm() >= 1e-4)
        placeTool(*toolPixel_, *center, false);
    else
        viewport_->setHoverCenter(center); // drawn on this picture all the same
}

void ViewportInput::hideTool() {
    toolPressed_ = false;
    toolPixel_.reset();
    viewport_->setHoverCenter(std::nullopt);
    if (!toolShown_) return;
    toolShown_ = false;
    sim_->setTool(toolTarget_, toolRadius_, false, false);
}

void ViewportInput::look(OrbitCamera camera) {
    const SheetSnapshot* snap = viewport_->snapshot();
    if (snap && snap->groundEnabled) camera.keepAbove(snap->groundHeight);
    viewport_->setCamera(camera);
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
    look(c);
    return true;
}

bool ViewportInput::eventFilter(QObject* watched, QEvent* event) {
    if (watched != viewport_) return false;
    const bool wasHolding = toolPressed();
    const bool handled = handle(event);
    sayIfHoldChanged(wasHolding);
    return handled;
}

bool ViewportInput::handle(QEvent* event) {
    if (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::Wheel) emit acted();
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
            look(c);
            return true;
        }
        if (move &&
            ((e->buttons() & Qt::MiddleButton) || ((e->buttons() & Qt::RightButton) && shift))) {
            OrbitCamera c = viewport_->camera();
            c.pan(-double(delta.x()) / viewport_->height(),
                  double(delta.y()) / viewport_->height());
            look(c);
            return true;
        }
        const bool left = e->buttons() & Qt::LeftButton;
        switch (tool_) {
        case Tool::Push:
            pointTool(pos, left);
            break;
        case Tool::Grab:
            useGrab(pos, left, event->type() == QEvent::MouseButtonPress);
            break;
        case Tool::Pin:
            usePin(pos, left);
            break;
        case Tool::Fold:
            useFold(pos, left, event->type() == QEvent::MouseButtonPress);
            break;
        }
        return true;
    }
    case QEvent::Wheel: {
        auto* e = static_cast<QWheelEvent*>(event);
        if (grabbing_) {
            // Nearer the eye (up, seen from above) or further away.
            grabPoint_ -= facing() * (kGrabWheelStep * e->angleDelta().y() / 120.0);
            useGrab(grabPixel_, true, false);
            return true;
        }
        if (!(e->modifiers() & Qt::ControlModifier)) return orbitPanOrZoom(event);
        const double notches = e->angleDelta().y() / 120.0;
        setToolRadius(std::clamp(toolRadius_ * std::pow(1.1, notches), 0.01, 0.10));
        emit toolRadiusChanged(toolRadius_);
        return true;
    }
    case QEvent::Leave:
        hideTool();
        return false;
    case QEvent::Enter:
        showToolUnderCursor();
        return false;
    case QEvent::KeyPress:
        if (!orbitPanOrZoom(event)) return false;
        emit acted();
        return true;
    default:
        return false;
    }
}

} // namespace pf
