#include "SimulationThread.h"

#include "SimulationWorker.h"

#include <condition_variable>
#include <mutex>

namespace pf {

SimulationThread::SimulationThread(World initial, QObject* parent) : QObject(parent) {
    qRegisterMetaType<std::shared_ptr<const World>>("std::shared_ptr<const World>");
    qRegisterMetaType<std::shared_ptr<const EditLog>>("std::shared_ptr<const EditLog>");
    qRegisterMetaType<pf::SimParams>("pf::SimParams");
    worker_ = new SimulationWorker(std::move(initial), this);
    worker_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    connect(this, &SimulationThread::commandsPosted, worker_, &SimulationWorker::runCommands,
            Qt::QueuedConnection);
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
    // QThread::wait synchronises inside Qt, where ThreadSanitizer cannot see it; the
    // worker's destructor signals through this lock, which it can.
    std::unique_lock lock(workerGoneMutex_);
    workerGoneChanged_.wait(lock, [this] { return workerGone_; });
}

void SimulationThread::markWorkerGone() {
    std::lock_guard lock(workerGoneMutex_);
    workerGone_ = true;
    workerGoneChanged_.notify_all();
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
    if (toWorker_.post(std::move(command))) emit commandsPosted(QPrivateSignal());
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
void SimulationThread::requestWorld(quint64 requestId) {
    PF_POST(copyWorld(requestId));
}
void SimulationThread::requestRecording(quint64 requestId) {
    PF_POST(copyRecording(requestId));
}

#undef PF_POST

void SimulationThread::sync() {
    // A condition variable rather than a blocking queued call: its wait is one that
    // ThreadSanitizer sees, so what the worker did is ordered before what follows here.
    std::mutex m;
    std::condition_variable applied;
    bool done = false;
    post([&](SimulationWorker&) {
        std::lock_guard lock(m);
        done = true;
        applied.notify_one();
    });
    std::unique_lock lock(m);
    applied.wait(lock, [&] { return done; });
}

} // namespace pf
