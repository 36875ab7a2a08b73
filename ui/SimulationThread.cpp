#include "SimulationThread.h"

#include "SimulationWorker.h"

#include <condition_variable>
#include <mutex>

namespace pf {

SimulationThread::SimulationThread(World initial, QObject* parent) : QObject(parent) {
    worker_ = new SimulationWorker(std::move(initial), channel_);
    forwardWorkerSignals();
    worker_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    channel_.wake = connect(this, &SimulationThread::commandsPosted, worker_,
                            &SimulationWorker::runCommands, Qt::QueuedConnection);
    connect(this, &SimulationThread::guiWorkPosted, this, &SimulationThread::deliverToGui,
            Qt::QueuedConnection);
    connect(this, &SimulationThread::snapshotPosted, this, &SimulationThread::notifySnapshot,
            Qt::QueuedConnection);
    thread_.setObjectName(QStringLiteral("simulation"));
    thread_.start();
    post([](SimulationWorker& w) { w.start(); });
}

SimulationThread::~SimulationThread() {
    thread_.quit();
    thread_.wait();
    channel_.waitForWorkerGone();
}

void SimulationThread::forwardWorkerSignals() {
    // Direct: these run on the simulation thread as the worker emits, and hand the
    // emission of this object's signal to the GUI thread.
    auto direct = [this](auto signal, auto forward) {
        connect(worker_, signal, this, forward, Qt::DirectConnection);
    };
    direct(&SimulationWorker::published,
           [this](std::shared_ptr<const SheetSnapshot> snapshot, const SimulationStatus& status) {
               publish(std::move(snapshot), status);
           });
    direct(&SimulationWorker::strokeRecorded, [this](int stroke, int events) {
        emitOnGuiThread([this, stroke, events] { emit strokeRecorded(stroke, events); });
    });
    direct(&SimulationWorker::strokeUndone, [this](int stroke, int n) {
        emitOnGuiThread([this, stroke, n] { emit strokeUndone(stroke, n); });
    });
    direct(&SimulationWorker::strokeRedone, [this](int stroke, int n) {
        emitOnGuiThread([this, stroke, n] { emit strokeRedone(stroke, n); });
    });
    direct(&SimulationWorker::settled,
           [this](int stroke) { emitOnGuiThread([this, stroke] { emit settled(stroke); }); });
    direct(&SimulationWorker::worldReplaced,
           [this] { emitOnGuiThread([this] { emit worldReplaced(); }); });
    direct(&SimulationWorker::diverged,
           [this](qint64 step) { emitOnGuiThread([this, step] { emit diverged(step); }); });
}

std::shared_ptr<const SheetSnapshot> SimulationThread::latestSnapshot() const {
    std::lock_guard lock(mutex_);
    return snapshot_;
}

SimulationStatus SimulationThread::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

void SimulationThread::publish(std::shared_ptr<const SheetSnapshot> snapshot,
                               const SimulationStatus& status) {
    {
        std::lock_guard lock(mutex_);
        snapshot_ = std::move(snapshot);
        status_ = status;
    }
    // One notification in flight at a time: a slow GUI skips frames instead of
    // piling up a queue of stale ones.
    if (!notifyPending_.exchange(true)) emit snapshotPosted(QPrivateSignal());
}

void SimulationThread::notifySnapshot() {
    notifyPending_ = false;
    emit snapshotReady();
}

void SimulationThread::emitOnGuiThread(std::function<void()> emitSignal) {
    if (toGui_.post(std::move(emitSignal))) emit guiWorkPosted(QPrivateSignal());
}

void SimulationThread::deliverToGui() {
    for (const auto& emitSignal : toGui_.takeAll()) emitSignal();
}

void SimulationThread::post(std::function<void(SimulationWorker&)> command) {
    if (channel_.commands.post(std::move(command))) emit commandsPosted(QPrivateSignal());
}

#define PF_POST(call) post([=](SimulationWorker& w) { w.call; })

void SimulationThread::setPlaying(bool playing) {
    PF_POST(setPlaying(playing));
}
void SimulationThread::stepOnce() {
    PF_POST(stepOnce());
}
void SimulationThread::setParams(const SimParams& params) {
    PF_POST(setParams(params));
}
void SimulationThread::replaceWorld(const World& world) {
    PF_POST(replaceWorld(world));
}
void SimulationThread::setTool(const Vec3& target, double radius, bool visible, bool pressed) {
    PF_POST(setTool(target, radius, visible, pressed));
}
void SimulationThread::undoStroke(int stroke) {
    PF_POST(undoStroke(stroke));
}
void SimulationThread::redoStroke(int stroke) {
    PF_POST(redoStroke(stroke));
}
void SimulationThread::settle() {
    PF_POST(settle());
}

#undef PF_POST

void SimulationThread::callOnWorker(const std::function<void(SimulationWorker&)>& read) {
    // From the simulation thread itself, or once it stopped, nothing would answer.
    Q_ASSERT(QThread::currentThread() != &thread_ && thread_.isRunning());
    // A condition variable rather than a blocking queued call: its wait is one that
    // ThreadSanitizer sees, so what the worker did is ordered before what follows here.
    std::mutex m;
    std::condition_variable applied;
    bool done = false;
    post([&](SimulationWorker& w) {
        read(w);
        std::lock_guard lock(m);
        done = true;
        applied.notify_one();
    });
    std::unique_lock lock(m);
    applied.wait(lock, [&] { return done; });
}

void SimulationThread::sync() {
    callOnWorker([](SimulationWorker&) {});
}

std::shared_ptr<const World> SimulationThread::copyWorld() {
    std::shared_ptr<const World> copy;
    callOnWorker(
        [&](SimulationWorker& w) { copy = std::make_shared<const World>(w.session().world()); });
    return copy;
}

std::shared_ptr<const EditLog> SimulationThread::copyRecording() {
    std::shared_ptr<const EditLog> copy;
    callOnWorker(
        [&](SimulationWorker& w) { copy = std::make_shared<const EditLog>(w.session().log()); });
    return copy;
}

} // namespace pf
