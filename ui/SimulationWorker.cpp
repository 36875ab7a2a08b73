#include "SimulationWorker.h"

#include "SheetStats.h"
#include "SimulationChannel.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cmath>

namespace pf {

SimulationWorker::SimulationWorker(World world, SimulationChannel& channel)
    : session_(std::move(world)), channel_(channel), timer_(this) {
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &SimulationWorker::frame);
}

SimulationWorker::~SimulationWorker() {
    // Drop the GUI's wake-up here, not in ~QObject: after markWorkerGone the GUI side
    // may be destroyed, and ~QObject would read it to disconnect.
    disconnect(channel_.wake);
    disconnect(); // and the forwarding to the GUI side, for the same reason
    channel_.markWorkerGone();
}

void SimulationWorker::runCommands() {
    for (const auto& command : channel_.commands.takeAll()) command(*this);
    announceRecounts();
}

void SimulationWorker::start() {
    timer_.start(kTickMilliseconds);
    publish();
}

void SimulationWorker::setPlaying(bool playing) {
    playing_ = playing;
    publish();
}

void SimulationWorker::stepOnce() {
    playing_ = false;
    QElapsedTimer t;
    t.start();
    advance(1);
    lastStepSeconds_ = t.nsecsElapsed() * 1e-9;
    publish();
}

void SimulationWorker::setThreads(int threads) {
    session_.simulation().setThreads(threads);
    publish();
}

void SimulationWorker::setParams(const SimParams& params) {
    session_.setParams(params);
    publish();
}

void SimulationWorker::replaceWorld(const World& world) {
    session_.replaceWorld(world);
    // A new sheet has taken no step: the last sheet's cost stood over it while paused.
    lastStepSeconds_ = 0.0;
    stepCost_ = 0.0;
    pacer_.restart();
    sinceTick_.invalidate(); // the time the new sheet took to arrive is not its step's

    publish();
    emit worldReplaced();
}

void SimulationWorker::setTool(const Vec3& target, double radius, bool visible, bool pressed) {
    editedSinceShown_ = true;
    const SphereTool before = session_.world().sphere;
    const auto ended = session_.setTool(target, radius, visible, pressed);
    announce(ended);
    if (before.active && !pressed && !ended) emit pushMovedNothing();
    // Paused, a frame is published only when the tool moves: one that appears under the
    // cursor (where it is put at once), goes or is pressed is shown now.
    const SphereTool& after = session_.world().sphere;
    if (!playing_ && (after.hovering != before.hovering || after.active != before.active))
        publish();
}

void SimulationWorker::grab(const Vec3& target, bool held, bool begin) {
    editedSinceShown_ = true;
    announce(session_.grab(target, held, begin));
}

void SimulationWorker::pin(const Vec3& point, double radius) {
    editedSinceShown_ = true;
    const auto ended = session_.pin(point, radius);
    announce(ended);
    if (ended) publish(); // the pins show while paused too
}

void SimulationWorker::fold(const FoldRequest& request) {
    editedSinceShown_ = true;
    const FoldRefusal refusal = session_.fold(request);
    emit foldAnswered(static_cast<int>(refusal));
    if (refusal == FoldRefusal::None) publish(); // the flap shows pinned while paused
}

void SimulationWorker::reset(const World& world) {
    editedSinceShown_ = true;
    const auto ended = session_.reset(world);
    announce(ended);
    if (ended) publish(); // the fresh sheet shows while paused too
}

void SimulationWorker::announce(const std::optional<EditSession::StrokeEnd>& ended) {
    if (ended) emit strokeRecorded(ended->stroke, ended->events, static_cast<int>(ended->kind));
}

void SimulationWorker::announceRecounts() {
    for (const EditSession::StrokeEnd& r : session_.takeRecounted())
        emit strokeRecounted(r.stroke, r.events);
}

void SimulationWorker::undoStroke(int stroke) {
    editedSinceShown_ = true;
    const auto recovered = session_.undoStroke(stroke);
    if (!recovered) {
        emit strokeUndoRefused(stroke);
        return;
    }
    emit strokeUndone(stroke, *recovered);
    publish();
}

void SimulationWorker::redoStroke(int stroke) {
    editedSinceShown_ = true;
    const auto reapplied = session_.redoStroke(stroke);
    if (reapplied)
        emit strokeRedone(stroke, *reapplied);
    else
        emit strokeRedoRefused(stroke);
    // Refused, it may still have taken back the damage since the last undo or redo (the
    // session's redoStroke): shown, also while paused.
    publish();
}

void SimulationWorker::settle() {
    editedSinceShown_ = true;
    const bool alreadySettled = session_.frozen();
    session_.settle();
    // Said, or the status bar's "Settling…" would stand over a sheet that does not settle.
    if (!session_.settling()) emit settleRefused(alreadySettled);
    // Refused (a settled sheet, say), the editor would wait for a Settle that never comes
    // (MainWindow::gateUndo) until something else published; paused, nothing does.
    publish();
}

void SimulationWorker::advance(int steps) {
    const StepStatus status = session_.advance(steps);
    if (const auto finished = session_.takeFinished()) {
        if (finished->kind == EditSession::StrokeKind::Settle)
            emit settled(finished->stroke);
        else
            announce(finished); // a fold that was let go
    }
    announceRecounts();
    if (session_.takeFoldOpening()) emit foldOpening();
    if (const auto notice =
            EditSession::foldNotice(session_.takeFoldTurnedBack(), session_.takeFoldLeftBehind(),
                                    session_.foldAskedDegrees())) {
        switch (notice->kind) {
        case EditSession::FoldNotice::Kind::SprangBack:
            emit foldSprangBack(notice->value);
            break;
        case EditSession::FoldNotice::Kind::FellShut:
            emit foldFellShut(notice->value);
            break;
        case EditSession::FoldNotice::Kind::ClosedFurther:
            emit foldClosedFurther(notice->value);
            break;
        case EditSession::FoldNotice::Kind::LeftPaperBehind:
            emit foldLeftPaperBehind(notice->value);
            break;
        }
    }
    if (status == StepStatus::Ok) return;
    playing_ = false;
    emit diverged(session_.world().stepCount);
}

void SimulationWorker::frame() {
    if (!playing_) {
        sinceTick_.invalidate();
        pacer_.restart();
        if (session_.placeToolAtTarget()) publish();
        return;
    }
    const double elapsed = sinceTick_.isValid() ? sinceTick_.nsecsElapsed() * 1e-9 : kFrameSeconds;
    sinceTick_.start();
    const int steps = pacer_.stepsFor(elapsed, session_.world().params.dt, stepCost_);
    if (steps == 0) return; // an early tick: the next one runs its steps
    const bool wasAsleep = session_.simulation().asleep();
    QElapsedTimer t;
    t.start();
    advance(steps);
    pacer_.stepped(steps, t.nsecsElapsed() * 1e-9);
    const double cost = t.nsecsElapsed() * 1e-9 / steps;
    // Averaged over the last few ticks, so that one slow tick (a break's new mesh, the
    // view taking the core) does not stop the catching up.
    stepCost_ = stepCost_ > 0.0 ? 0.8 * stepCost_ + 0.2 * cost : cost;
    lastStepSeconds_ = cost;
    lastTickAsleep_ = wasAsleep && session_.simulation().asleep();
    // A sleeping sheet is the picture already shown: making, hashing and comparing a
    // new one each frame kept 42 % of a core busy at 14,100 vertices (83,160 springs)
    // with nothing to show, and the view 11 % comparing it with the last.
    if (wasAsleep && shownStillShows())
        republish();
    else
        publish();
}

bool SimulationWorker::shownStillShows() const {
    const Simulation& sim = session_.simulation();
    const World& w = sim.world();
    if (!shown_ || editedSinceShown_ || !sim.asleep()) return false;
    const SheetSnapshot& s = *shown_;
    // Recent breaks fade with the clock (read from the picture: the status counts a
    // second of steps rounded, the picture rounded up).
    if (std::ranges::find(s.recentlyBroken, std::uint8_t{1}) != s.recentlyBroken.end())
        return false;
    if (!toolDrawsTheSame(s.sphere, w.sphere) || s.groundEnabled != w.groundEnabled ||
        s.groundHeight != w.groundHeight)
        return false;
    const Sheet& sheet = w.sheet;
    if (s.tris.size() != sheet.tris.size() ||
        s.springEnds.size() != static_cast<std::size_t>(sheet.springs.size()) ||
        s.x != sheet.verts.x || shownVelocities_ != sheet.verts.v)
        return false;
    std::vector<Index> pinned, held;
    pinnedAndHeld(sim, pinned, held);
    return pinned == s.pinned && held == s.held;
}

void SimulationWorker::setClock(SimulationStatus& st) const {
    st.step = session_.world().stepCount;
    // Playing, over the same second as the pace, so that the two agree; paused (or in
    // the first second of play), the last step's own. Asleep and playing, a tick's
    // steps that were all asleep (0 until there is one): the second before, and the tick
    // the sheet fell asleep in, held awake steps, and a user read "step 13834 µs · at
    // rest".
    const bool asleep = session_.simulation().asleep();
    st.stepSeconds = playing_ && asleep ? (lastTickAsleep_ ? lastStepSeconds_ : 0.0)
                     : playing_ && pacer_.stepSeconds() > 0.0 ? pacer_.stepSeconds()
                                                              : lastStepSeconds_;
    st.threads = session_.simulation().threads();
    st.playing = playing_;
    st.pace = pacer_.pace();
    st.folding = session_.folding();
    st.settling = session_.settling();
    st.settled = session_.frozen();
    st.asleep = asleep;
}

void SimulationWorker::republish() {
    SimulationStatus st = shownStatus_;
    setClock(st);
    emit published(shown_, st);
}

void SimulationWorker::publish() {
    const World& w = session_.world();
    SimulationStatus st;
    setClock(st);
    st.vertices = w.sheet.verts.size();
    st.springs = w.sheet.springs.size();
    const SheetStats stats = computeStats(w.sheet);
    st.breaks = stats.breaks;
    st.hinges = stats.hinges;
    const auto secondOfSteps = static_cast<std::int64_t>(std::lround(1.0 / w.params.dt));
    st.breaksLastSecond = static_cast<int>(breaksSince(w.sheet, w.stepCount - secondOfSteps));
    st.maxStretch = stats.maxStretch;
    st.rmsStretch = stats.rmsStretch;
    st.sheetHash = editedStateHash(w.sheet);
    st.grabHeldBack = session_.grabHeldBack();
    shown_ = std::make_shared<const SheetSnapshot>(makeSnapshot(session_.simulation()));
    shownStatus_ = st;
    shownVelocities_ = w.sheet.verts.v;
    editedSinceShown_ = false;
    emit published(shown_, st);
}

} // namespace pf
