#include "SimulationWorker.h"

#include "SheetStats.h"
#include "SimulationThread.h"

#include <QElapsedTimer>
#include <cmath>

namespace pf {

SimulationWorker::SimulationWorker(World world, SimulationThread* owner)
    : session_(std::move(world)), owner_(owner), timer_(this) {
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
    session_.setParams(params);
    owner_->emitOnGuiThread([o = owner_, params] { emit o->paramsApplied(params); });
    publish(0.0);
}

void SimulationWorker::replaceWorld(const World& world) {
    session_.replaceWorld(world);
    publish(0.0);
    owner_->emitOnGuiThread([o = owner_] { emit o->worldReplaced(); });
}

void SimulationWorker::setTool(const Vec3& target, double radius, bool visible, bool pressed) {
    const auto ended = session_.setTool(target, radius, visible, pressed);
    if (!ended) return;
    owner_->emitOnGuiThread([o = owner_, stroke = ended->stroke, count = ended->events] {
        emit o->strokeRecorded(stroke, count);
    });
}

void SimulationWorker::undoStroke(int stroke) {
    const auto recovered = session_.undoStroke(stroke);
    if (!recovered) return;
    owner_->emitOnGuiThread(
        [o = owner_, stroke, n = *recovered] { emit o->strokeUndone(stroke, n); });
    publish(0.0);
}

void SimulationWorker::redoStroke(int stroke) {
    const auto reapplied = session_.redoStroke(stroke);
    if (!reapplied) return;
    owner_->emitOnGuiThread(
        [o = owner_, stroke, n = *reapplied] { emit o->strokeRedone(stroke, n); });
    publish(0.0);
}

void SimulationWorker::copyWorld(quint64 requestId) {
    owner_->emitOnGuiThread(
        [o = owner_, requestId, world = std::make_shared<const World>(session_.world())] {
            emit o->worldCopied(requestId, world);
        });
}

void SimulationWorker::copyRecording(quint64 requestId) {
    owner_->emitOnGuiThread(
        [o = owner_, requestId, log = std::make_shared<const EditLog>(session_.log())] {
            emit o->recordingCopied(requestId, log);
        });
}

void SimulationWorker::advance(int steps) {
    if (session_.advance(steps) == StepStatus::Ok) return;
    playing_ = false;
    owner_->emitOnGuiThread(
        [o = owner_, step = session_.world().stepCount] { emit o->diverged(step); });
}

void SimulationWorker::frame() {
    if (!playing_) {
        if (session_.placeToolAtTarget()) publish(0.0);
        return;
    }
    const int steps =
        std::max(1, static_cast<int>(std::lround(kFrameSeconds / session_.world().params.dt)));
    QElapsedTimer t;
    t.start();
    advance(steps);
    publish(t.nsecsElapsed() * 1e-9 / steps);
}

void SimulationWorker::publish(double stepSeconds) {
    const World& w = session_.world();
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
