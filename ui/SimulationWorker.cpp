#include "SimulationWorker.h"

#include "Breaking.h"
#include "Hinges.h"
#include "Normals.h"
#include "Scenes.h"
#include "SheetStats.h"
#include "SimulationThread.h"

#include <QElapsedTimer>
#include <cmath>

namespace pf {

namespace {

// The tool follows the cursor, but no faster than this: a jump across the sheet
// must not teleport through the paper.
constexpr double kMaxToolSpeed = 1.5; // m/s

} // namespace

SimulationWorker::SimulationWorker(World world, SimulationThread* owner)
    : sim_(std::move(world)), owner_(owner), timer_(this) {
    // The editor drives the sphere; a scene's scripted path would fight the mouse.
    sim_.world().script.sphereKeys.clear();
    toolTarget_ = sim_.world().sphere.center;
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &SimulationWorker::frame);
}

SimulationWorker::~SimulationWorker() {
    // Drop the connections from the owner here, not in ~QObject: after markWorkerGone
    // the owner may be destroyed, and ~QObject would read it to disconnect.
    disconnect(owner_, nullptr, this, nullptr);
    owner_->markWorkerGone();
}

void SimulationWorker::runCommands() {
    for (const auto& command : owner_->toWorker_.takeAll()) command(*this);
}

void SimulationWorker::start() {
    timer_.start(static_cast<int>(std::lround(kFrameSeconds * 1000)));
    publish(0.0);
}

void SimulationWorker::setPlaying(bool playing) {
    playing_ = playing;
    publish(0.0);
}

void SimulationWorker::stepOnce() {
    playing_ = false;
    QElapsedTimer t;
    t.start();
    advance(1);
    publish(t.nsecsElapsed() * 1e-9);
}

void SimulationWorker::setParams(const SimParams& params) {
    // A different paper weighs differently: the masses follow its areal density.
    if (!(params.material == sim_.world().params.material))
        setMaterial(sim_.world(), params.material);
    sim_.world().params = params;
    owner_->emitOnGuiThread([o = owner_, params] { emit o->paramsApplied(params); });
    publish(0.0);
}

void SimulationWorker::replaceWorld(const World& world) {
    const bool wasPressed = pressed_;
    const SphereTool tool = sim_.world().sphere;
    sim_ = Simulation(world);
    sim_.world().script.sphereKeys.clear();
    sim_.world().sphere.radius = tool.radius;
    sim_.world().sphere.active = tool.active;
    strokes_.clear();
    pressed_ = wasPressed;
    strokeStart_ = static_cast<Index>(sim_.world().sheet.events.size());
    publish(0.0);
    owner_->emitOnGuiThread([o = owner_] { emit o->worldReplaced(); });
}

void SimulationWorker::setTool(const Vec3& target, double radius, bool visible, bool pressed) {
    SphereTool& sphere = sim_.world().sphere;
    toolTarget_ = target;
    sphere.radius = radius;
    if (visible && !sphere.active) sphere.center = target; // appears where the cursor is
    sphere.active = visible;
    if (pressed && !pressed_) strokeStart_ = static_cast<Index>(sim_.world().sheet.events.size());
    const bool released = pressed_ && !pressed;
    pressed_ = pressed;
    if (released) endStroke();
}

void SimulationWorker::endStroke() {
    const Sheet& s = sim_.world().sheet;
    std::vector<StrokeEvent> events;
    for (Index e = strokeStart_; e < static_cast<Index>(s.events.size()); ++e) {
        const DamageEvent& ev = s.events[e];
        if (!ev.active) continue;
        StrokeEvent se{e, ev.kind, ev.edge, 0.0};
        if (ev.kind == EventKind::Hinge) se.hingeRest = s.springs.rest[ev.springs[0]];
        events.push_back(se);
    }
    if (events.empty()) return;
    strokes_.push_back(std::move(events));
    const int stroke = static_cast<int>(strokes_.size()) - 1;
    const int count = static_cast<int>(strokes_.back().size());
    owner_->emitOnGuiThread([o = owner_, stroke, count] { emit o->strokeRecorded(stroke, count); });
}

void SimulationWorker::undoStroke(int stroke) {
    if (stroke < 0 || stroke >= static_cast<int>(strokes_.size())) return;
    int recovered = 0;
    auto& events = strokes_[static_cast<std::size_t>(stroke)];
    for (auto it = events.rbegin(); it != events.rend(); ++it)
        recovered += recoverEvent(sim_.world().sheet, it->event) ? 1 : 0;
    owner_->emitOnGuiThread(
        [o = owner_, stroke, recovered] { emit o->strokeUndone(stroke, recovered); });
    publish(0.0);
}

void SimulationWorker::redoStroke(int stroke) {
    if (stroke < 0 || stroke >= static_cast<int>(strokes_.size())) return;
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
    owner_->emitOnGuiThread(
        [o = owner_, stroke, reapplied] { emit o->strokeRedone(stroke, reapplied); });
    publish(0.0);
}

void SimulationWorker::copyWorld(quint64 requestId) {
    owner_->emitOnGuiThread(
        [o = owner_, requestId, world = std::make_shared<const World>(sim_.world())] {
            emit o->worldCopied(requestId, world);
        });
}

void SimulationWorker::advance(int steps) {
    World& w = sim_.world();
    for (int k = 0; k < steps; ++k) {
        SphereTool& sphere = w.sphere;
        Vec3 move = toolTarget_ - sphere.center;
        const double limit = kMaxToolSpeed * w.params.dt;
        if (move.norm() > limit) move *= limit / move.norm();
        sphere.center += move;
        sphere.velocity = move / w.params.dt;
        if (sim_.step() != StepStatus::Ok) {
            playing_ = false;
            owner_->emitOnGuiThread([o = owner_, step = w.stepCount] { emit o->diverged(step); });
            return;
        }
    }
}

void SimulationWorker::frame() {
    if (!playing_) {
        // Paused: the tool still moves to where the user points, without stepping.
        SphereTool& sphere = sim_.world().sphere;
        if ((sphere.center - toolTarget_).squaredNorm() > 0.0) {
            sphere.center = toolTarget_;
            publish(0.0);
        }
        return;
    }
    const int steps =
        std::max(1, static_cast<int>(std::lround(kFrameSeconds / sim_.world().params.dt)));
    QElapsedTimer t;
    t.start();
    advance(steps);
    publish(t.nsecsElapsed() * 1e-9 / steps);
}

void SimulationWorker::publish(double stepSeconds) {
    const World& w = sim_.world();
    SimulationStatus st;
    st.step = w.stepCount;
    st.stepSeconds = stepSeconds;
    st.vertices = w.sheet.verts.size();
    st.springs = w.sheet.springs.size();
    const SheetStats stats = computeStats(w.sheet);
    st.breaks = stats.breaks;
    st.hinges = stats.hinges;
    st.maxStrain = stats.maxStrain;
    st.rmsStrain = stats.rmsStrain;
    st.playing = playing_;
    owner_->publish(std::make_shared<const SheetSnapshot>(makeSnapshot(w)), st);
}

} // namespace pf
