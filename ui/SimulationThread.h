#pragma once

#include "CrossThreadQueue.h"
#include "EditSession.h"
#include "SheetSnapshot.h"
#include "World.h"

#include <QObject>
#include <QThread>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>

namespace pf {

class SimulationWorker;

// Live statistics of the running simulation, for the status bar and the tests.
struct SimulationStatus {
    std::int64_t step = 0;
    double stepSeconds = 0.0; // wall time of one step, averaged over the last frame
    int vertices = 0, springs = 0, breaks = 0, hinges = 0;
    double maxStrain = 0.0, rmsStrain = 0.0; // |l/l0 - 1| over structural springs
    bool playing = false;
};

// The simulation on its own thread. The GUI talks to it only through these
// methods, which queue a command that the thread applies between frames, and reads
// the newest published snapshot. Nothing here blocks on a step. Signals arrive on
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
    void replaceWorld(const World& world); // New, Open, Reset
    // The tool: where the user points (target centre), its radius, and whether the
    // mouse button is down (a push stroke lasts from press to release).
    void setTool(const Vec3& target, double radius, bool visible, bool pressed);
    void undoStroke(int stroke);
    void redoStroke(int stroke);
    // Asks for a copy of the whole World; answered by worldCopied(requestId, ...).
    void requestWorld(quint64 requestId);
    // Asks for the session since the last New or Open, as a recording; answered by
    // recordingCopied(requestId, ...).
    void requestRecording(quint64 requestId);

    // Waits until every command queued so far has been applied (tests and shutdown only).
    void sync();

  signals:
    void snapshotReady();
    // A push stroke ended that broke or hinged something: it can be undone as one step.
    void strokeRecorded(int stroke, int events);
    void strokeUndone(int stroke, int recovered);
    void strokeRedone(int stroke, int reapplied);
    void worldCopied(quint64 requestId, std::shared_ptr<const World> world);
    void recordingCopied(quint64 requestId, std::shared_ptr<const EditLog> log);
    // A replaceWorld was applied: the old World is gone and a snapshot of the new one
    // was published (its snapshotReady comes first).
    void worldReplaced();
    void paramsApplied(const pf::SimParams& params);
    void diverged(qint64 step);

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
    friend class SimulationWorker;
    void publish(std::shared_ptr<const SheetSnapshot> snapshot, const SimulationStatus& status);
    // Called on the simulation thread: `emitSignal` runs (and emits) on the GUI thread.
    void emitOnGuiThread(std::function<void()> emitSignal);
    void post(std::function<void(SimulationWorker&)> command);
    // Called last by the worker's destructor, on the simulation thread.
    void markWorkerGone();

    CrossThreadQueue<SimulationWorker&> toWorker_;
    CrossThreadQueue<> toGui_;
    std::mutex workerGoneMutex_;
    std::condition_variable workerGoneChanged_;
    bool workerGone_ = false;

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
