#pragma once

#include "EditSession.h"
#include "FramePacer.h"
#include "SheetSnapshot.h"
#include "SimulationStatus.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <memory>

namespace pf {

class SimulationChannel;

// Owns the editing session; lives on the simulation thread. Every command runs there,
// between frames, so commands never interleave with a step. Its signals are emitted on
// the simulation thread (SimulationThread carries them to the GUI).
class SimulationWorker : public QObject {
    Q_OBJECT

  public:
    SimulationWorker(World world, SimulationChannel& channel);
    ~SimulationWorker() override;

    static constexpr double kFrameSeconds = FramePacer::kFrameSeconds;
    // The frame timer's period. A timer counts whole milliseconds: 17 ms (1/60 s rounded)
    // ticked 58.8 times a second, so the view could never show 60 frames. 16 ms ticks 62.5
    // times; the pacer runs the steps each tick is due, so the sheet keeps real time.
    static constexpr int kTickMilliseconds = 16;

    void start();
    void setPlaying(bool playing);
    void stepOnce();
    void setParams(const SimParams& params);
    void setThreads(int threads);
    void replaceWorld(const World& world);
    void setTool(const Vec3& target, double radius, bool visible, bool pressed);
    void grab(const Vec3& target, bool held, bool begin);
    void pin(const Vec3& point, double radius);
    void fold(const FoldRequest& request);
    void reset(const World& world);
    void undoStroke(int stroke);
    void redoStroke(int stroke);
    void settle();
    void answer() { emit answered(); }
    const EditSession& session() const { return session_; }

    // Applies every command the GUI queued.
    void runCommands();

  signals:
    void published(std::shared_ptr<const pf::SheetSnapshot> snapshot,
                   const pf::SimulationStatus& status);
    void strokeRecorded(int stroke, int events, int kind);
    // A push let go that changed nothing (no step to undo): the tool slid over paper it
    // could not move, or touched none.
    void pushMovedNothing();
    // A step's breaks and hinges now count `events` (EditSession::takeRecounted).
    void strokeRecounted(int stroke, int events);
    // The session refused an undo or a redo of `stroke` (EditSession::undoStroke): the
    // sheet is not as that step left it, or found it.
    void strokeUndoRefused(int stroke);
    void strokeRedoRefused(int stroke);
    void answered(); // SimulationThread::awaitAnswer
    void strokeUndone(int stroke, int recovered);
    void strokeRedone(int stroke, int reapplied);
    void settled(int stroke);                // a Settle froze the sheet: an undo step
    void settleRefused(bool alreadySettled); // the session did not begin the Settle
    void foldAnswered(int refusal);          // a FoldRefusal
    void foldSprangBack(double degrees);
    void foldFellShut(double asked);        // closed flat from a fold to that angle
    void foldClosedFurther(double degrees); // closed that much past the angle asked, not flat
    void foldOpening(); // within the second after the let-go (EditSession::takeFoldOpening)
    void foldLeftPaperBehind(double share);
    void worldReplaced();
    void diverged(qint64 step);

  private:
    void frame();
    void advance(int steps);
    void publish();
    // Whether the snapshot last published still shows the sheet: it sleeps, no edit has
    // come since, and nothing a sleeping step can change on its own (the tool, the pins, a
    // hand's grip, the positions) has changed.
    bool shownStillShows() const;
    // The status's clock: the step, the last step's cost, and what the worker and the
    // session are doing (playing, pace, folding, asleep).
    void setClock(SimulationStatus& status) const;
    // Publishes the snapshot shown again, with the status's clock brought up to date.
    void republish();
    void announce(const std::optional<EditSession::StrokeEnd>& ended);
    void announceRecounts();

    EditSession session_;
    SimulationChannel& channel_;
    QTimer timer_;
    FramePacer pacer_;
    QElapsedTimer sinceTick_; // reset by a tick while paused: the first tick of play is a frame
    double stepCost_ = 0.0;   // wall seconds a step has taken lately (FramePacer)
    // What the last step took. An edit's status shows it too: every edit read "step 0 µs"
    // until the next frame's steps (a user saw "step 0 µs · 0.11× real time" after an undo).
    double lastStepSeconds_ = 0.0;
    // Whether the sheet slept through the last tick from its start, so that
    // lastStepSeconds_ is a sleeping step's cost.
    bool lastTickAsleep_ = false;
    bool playing_ = true;
    // The last snapshot and status published, the velocities they were made from, and
    // whether an edit has come since (an edit may change what no comparison covers; a
    // command that only reads, as Save's copy of the world, is not one).
    std::shared_ptr<const SheetSnapshot> shown_;
    SimulationStatus shownStatus_;
    std::vector<Vec3> shownVelocities_;
    bool editedSinceShown_ = true;
};

} // namespace pf
