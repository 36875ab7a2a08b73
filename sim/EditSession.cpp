#include "EditSession.h"

#include "Breaking.h"
#include "Hinges.h"
#include "Normals.h"
#include "Scenes.h"

namespace pf {

EditSession::EditSession(World world) : sim_(std::move(world)) {
    // The user drives the sphere; a scene's scripted path would fight the mouse.
    sim_.world().script.sphereKeys.clear();
    toolTarget_ = sim_.world().sphere.center;
}

void EditSession::replaceWorld(const World& world) {
    const SphereTool tool = sim_.world().sphere;
    sim_ = Simulation(world);
    sim_.world().script.sphereKeys.clear();
    sim_.world().sphere.radius = tool.radius;
    sim_.world().sphere.active = tool.active;
    strokes_.clear();
    strokeStart_ = static_cast<Index>(sim_.world().sheet.events.size());
}

void EditSession::setParams(const SimParams& params) {
    if (!(params.material == sim_.world().params.material))
        setMaterial(sim_.world(), params.material);
    sim_.world().params = params;
}

std::optional<EditSession::StrokeEnd> EditSession::setTool(const Vec3& target, double radius,
                                                           bool visible, bool pressed) {
    SphereTool& sphere = sim_.world().sphere;
    toolTarget_ = target;
    sphere.radius = radius;
    if (visible && !sphere.active) sphere.center = target; // appears where the cursor is
    sphere.active = visible;
    if (pressed && !pressed_) strokeStart_ = static_cast<Index>(sim_.world().sheet.events.size());
    const bool released = pressed_ && !pressed;
    pressed_ = pressed;
    return released ? endStroke() : std::nullopt;
}

std::optional<EditSession::StrokeEnd> EditSession::endStroke() {
    const Sheet& s = sim_.world().sheet;
    std::vector<StrokeEvent> events;
    for (Index e = strokeStart_; e < static_cast<Index>(s.events.size()); ++e) {
        const DamageEvent& ev = s.events[e];
        if (!ev.active) continue;
        StrokeEvent se{e, ev.kind, ev.edge, 0.0};
        if (ev.kind == EventKind::Hinge) se.hingeRest = s.springs.rest[ev.springs[0]];
        events.push_back(se);
    }
    if (events.empty()) return std::nullopt;
    strokes_.push_back(std::move(events));
    return StrokeEnd{static_cast<int>(strokes_.size()) - 1,
                     static_cast<int>(strokes_.back().size())};
}

std::optional<int> EditSession::undoStroke(int stroke) {
    if (stroke < 0 || stroke >= static_cast<int>(strokes_.size())) return std::nullopt;
    int recovered = 0;
    auto& events = strokes_[static_cast<std::size_t>(stroke)];
    for (auto it = events.rbegin(); it != events.rend(); ++it)
        recovered += recoverEvent(sim_.world().sheet, it->event) ? 1 : 0;
    return recovered;
}

std::optional<int> EditSession::redoStroke(int stroke) {
    if (stroke < 0 || stroke >= static_cast<int>(strokes_.size())) return std::nullopt;
    World& w = sim_.world();
    Sheet& s = w.sheet;
    int reapplied = 0;
    std::vector<Vec3> normals;
    for (StrokeEvent& se : strokes_[static_cast<std::size_t>(stroke)]) {
        // Undone in reverse order, the edges have their old ids again.
        if (se.edge < 0 || se.edge >= s.springs.size()) continue;
        if (se.kind == EventKind::Break) {
            if (!canBreak(s, se.edge)) continue;
            computeVertexNormals(s, normals);
            se.event = breakEdge(s, se.edge, normals, w.params.psi, w.stepCount);
        } else {
            if (!canHinge(s, se.edge)) continue;
            se.event = insertHinge(s, se.edge, se.hingeRest, w.stepCount);
        }
        ++reapplied;
    }
    return reapplied;
}

StepStatus EditSession::advance(int steps) {
    World& w = sim_.world();
    for (int k = 0; k < steps; ++k) {
        SphereTool& sphere = w.sphere;
        Vec3 move = toolTarget_ - sphere.center;
        const double limit = kMaxToolSpeed * w.params.dt;
        if (move.norm() > limit) move *= limit / move.norm();
        sphere.center += move;
        sphere.velocity = move / w.params.dt;
        const StepStatus status = sim_.step();
        if (status != StepStatus::Ok) return status;
    }
    return StepStatus::Ok;
}

bool EditSession::placeToolAtTarget() {
    SphereTool& sphere = sim_.world().sphere;
    if ((sphere.center - toolTarget_).squaredNorm() == 0.0) return false;
    sphere.center = toolTarget_;
    return true;
}

} // namespace pf
