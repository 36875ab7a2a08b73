#pragma once

#include "CrossThreadQueue.h"
#include "EditSession.h"
#include "SheetSnapshot.h"
#include "SimulationChannel.h"
#include "SimulationStatus.h"
#include "World.h"

#include <QObject>
#include <QThread>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>

namespace pf {

class SimulationWorker;

// The simulation on its own thread. The GUI talks to it only through these
// methods, which queue a command that the thread applies between frames, and reads
// the newest published snapshot. Only copyWorld, copyRecording and sync wait: for the
// frame under way and the commands queued before them. Signals arrive on
// the GUI thread.
class SimulationThread : public QObject {
    Q_OBJECT

  public:
    explicit SimulationThread(World initial, QObject* parent = nullptr);
    ~SimulationThread() override; // stops the thread cleanly

    std::shared_ptr<const SheetSnapshot> latestSnapshot() const;
    SimulationStatus status() const;

    // Commands, applied in order between frames.
    void setPlaying(bool playing);
    void stepOnce();
    void setParams(const SimParams& params);
    // The threads the step runs on (Simulation::setThreads): not an edit of the sheet.
    void setThreads(int threads);
    void replaceWorld(const World& world); // New, Open
    // The tool: where the user points (target centre), its radius, and whether the
    // mouse button is down (a push stroke lasts from press to release).
    void setTool(const Vec3& target, double radius, bool visible, bool pressed);
    // The grab tool: pulls the sheet's vertex nearest to where the grab began toward
    // `target` while held (EditSession::grab).
    void grab(const Vec3& target, bool held, bool begin);
    // The pin tool: toggles the pins within `radius` of `point` (EditSession::pin).
    void pin(const Vec3& point, double radius);
    // The fold tool (EditSession::fold); answered by foldAnswered, and by strokeRecorded
    // once the fold is let go.
    void fold(const FoldRequest& request);
    // Simulation ▸ Reset: the sheet starts again from `world`, as an undo step
    // (EditSession::reset), unlike replaceWorld.
    void reset(const World& world);
    // Each is answered (strokeUndone or strokeUndoRefused, strokeRedone or
    // strokeRedoRefused) before awaitingAnswers() is false again.
    void undoStroke(int stroke);
    void redoStroke(int stroke);
    // What the simulation thread makes of everything sent so far reaches the GUI before
    // awaitingAnswers() is false again: after a release, the step it made (strokeRecorded).
    void awaitAnswer();
    // Commands sent with undoStroke, redoStroke or awaitAnswer not answered yet. The
    // History waits meanwhile: it moves at a click, and a click before the answer to the
    // last one (a Ctrl+Z right after a push's release, before the push was in the
    // History) undid the step before it.
    bool awaitingAnswers() const { return unanswered_ > 0; }
    // Lets the sheet come to rest without damage and keeps it so until the next edit
    // (EditSession::settle); answered by settled() once it is frozen.
    void settle();
    // A copy of the whole World, and the session since the last New or Open as a
    // recording. They wait for the simulation thread to finish its frame (a save is
    // worth that), without a nested event loop: nothing else runs meanwhile.
    World copyWorld();
    EditLog copyRecording();

    // Waits until every command queued so far has been applied (tests only).
    void sync();

  signals:
    void snapshotReady();
    // A push or grab stroke ended that changed the sheet, or a pin was set or taken:
    // it can be undone as one step. `kind` is an EditSession::StrokeKind; `events` the
    // breaks and hinges it made, or the vertices it (un)pinned.
    void strokeRecorded(int stroke, int events, int kind);
    // A push let go that changed nothing (no step to undo): the tool slid over paper it
    // could not move, or touched none.
    void pushMovedNothing();
    // A step's breaks and hinges now count `events`: it took what the sheet broke
    // settling after it, or gave back what a later step's redo took back.
    void strokeRecounted(int stroke, int events);
    // The session refused an undo or a redo of `stroke`: the History steps back.
    void strokeUndoRefused(int stroke);
    void strokeRedoRefused(int stroke);
    void strokeUndone(int stroke, int recovered);
    void strokeRedone(int stroke, int reapplied);
    void settled(int stroke);
    // The session did not begin a Settle: the sheet was settled already (frozen, as the
    // last Settle left it) or an edit was under way.
    void settleRefused(bool alreadySettled);
    // `refusal` is a FoldRefusal: None when the fold began.
    void foldAnswered(int refusal);
    // A second after a fold was let go its flap had turned back this far, past
    // EditSession::kSprangBack: the crease did not keep it.
    void foldSprangBack(double degrees);
    void foldFellShut(double asked);        // closed flat from a fold to that angle
    void foldClosedFurther(double degrees); // closed that much past the angle asked, not flat
    void foldOpening();
    // At the same time, unless the flap sprang back: this share (0..1) of the paper on the
    // flap's side, at least EditSession::kLeftBehindShare, was not held by the carry and lies
    // unfolded.
    void foldLeftPaperBehind(double share);
    // A replaceWorld was applied: the old World is gone and a snapshot of the new one
    // was published (its snapshotReady comes first).
    void worldReplaced();
    void diverged(qint64 step);
    void allAnswered(); // awaitingAnswers() became false

    // Internal wake-ups, connected queued at construction. They carry nothing and name
    // no object, so no data and no object crosses threads through Qt's (to
    // ThreadSanitizer invisible) event queue: the data goes through CrossThreadQueue.
    void commandsPosted(QPrivateSignal);
    void guiWorkPosted(QPrivateSignal);
    void snapshotPosted(QPrivateSignal);

  private slots:
    // Woken by the simulation thread; they run on the GUI thread.
    void notifySnapshot();
    void deliverToGui();

  private:
    // Called on the simulation thread.
    void publish(std::shared_ptr<const SheetSnapshot> snapshot, const SimulationStatus& status);
    // Called on the simulation thread: `emitSignal` runs (and emits) on the GUI thread.
    void emitOnGuiThread(std::function<void()> emitSignal);
    // Carries the worker's signals to this object's, on the GUI thread.
    void forwardWorkerSignals();
    void post(std::function<void(SimulationWorker&)> command);
    // Runs `read` on the simulation thread between frames and waits for it.
    void callOnWorker(const std::function<void(SimulationWorker&)>& read);

    int unanswered_ = 0; // GUI thread only
    SimulationChannel channel_;
    CrossThreadQueue<> toGui_;

    QThread thread_;
    SimulationWorker* worker_ = nullptr; // lives on thread_
    // A standard mutex, not QMutex: ThreadSanitizer sees its every lock (QMutex's
    // contended path runs inside uninstrumented Qt), so the race check stays exact.
    mutable std::mutex mutex_;
    std::shared_ptr<const SheetSnapshot> snapshot_;
    SimulationStatus status_;
    std::atomic<bool> notifyPending_{false};
};

} // namespace pf
