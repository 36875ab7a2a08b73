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
    connect(worker_, &SimulationWorker::published, this, &SimulationThread::publish,
            Qt::DirectConnection);
    auto forward = [this](auto workerSignal, auto ownSignal) {
        connect(
            worker_, workerSignal, this,
            [this, ownSignal](auto... args) {
                emitOnGuiThread([this, ownSignal, args...] { (this->*ownSignal)(args...); });
            },
            Qt::DirectConnection);
    };
    forward(&SimulationWorker::strokeRecorded, &SimulationThread::strokeRecorded);
    forward(&SimulationWorker::pushMovedNothing, &SimulationThread::pushMovedNothing);
    forward(&SimulationWorker::strokeRecounted, &SimulationThread::strokeRecounted);
    forward(&SimulationWorker::strokeUndoRefused, &SimulationThread::strokeUndoRefused);
    forward(&SimulationWorker::strokeRedoRefused, &SimulationThread::strokeRedoRefused);
    forward(&SimulationWorker::strokeUndone, &SimulationThread::strokeUndone);
    forward(&SimulationWorker::strokeRedone, &SimulationThread::strokeRedone);
    forward(&SimulationWorker::settled, &SimulationThread::settled);
    forward(&SimulationWorker::settleRefused, &SimulationThread::settleRefused);
    forward(&SimulationWorker::foldAnswered, &SimulationThread::foldAnswered);
    forward(&SimulationWorker::foldSprangBack, &SimulationThread::foldSprangBack);
    forward(&SimulationWorker::foldOpening, &SimulationThread::foldOpening);
    forward(&SimulationWorker::foldFellShut, &SimulationThread::foldFellShut);
    forward(&SimulationWorker::foldClosedFurther, &SimulationThread::foldClosedFurther);
    forward(&SimulationWorker::foldLeftPaperBehind, &SimulationThread::foldLeftPaperBehind);
    forward(&SimulationWorker::worldReplaced, &SimulationThread::worldReplaced);
    forward(&SimulationWorker::diverged, &SimulationThread::diverged);
    connect(
        worker_, &SimulationWorker::answered, this,
        [this] {
            emitOnGuiThread([this] {
                if (--unanswered_ == 0) emit allAnswered();
            });
        },
        Qt::DirectConnection);
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
void SimulationThread::setThreads(int threads) {
    PF_POST(setThreads(threads));
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
void SimulationThread::grab(const Vec3& target, bool held, bool begin) {
    PF_POST(grab(target, held, begin));
}
void SimulationThread::pin(const Vec3& point, double radius) {
    PF_POST(pin(point, radius));
}
void SimulationThread::fold(const FoldRequest& request) {
    PF_POST(fold(request));
}
void SimulationThread::reset(const World& world) {
    PF_POST(reset(world));
}
void SimulationThread::undoStroke(int stroke) {
    PF_POST(undoStroke(stroke));
    awaitAnswer();
}
void SimulationThread::redoStroke(int stroke) {
    PF_POST(redoStroke(stroke));
    awaitAnswer();
}
void SimulationThread::awaitAnswer() {
    ++unanswered_;
    // Commands are applied in order and the signals they emit reach the GUI in order, so
    // this comes after every answer to what was sent before it.
    PF_POST(answer());
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

World SimulationThread::copyWorld() {
    World copy;
    callOnWorker([&](SimulationWorker& w) { copy = w.session().worldToSave(); });
    return copy;
}

EditLog SimulationThread::copyRecording() {
    EditLog copy;
    callOnWorker([&](SimulationWorker& w) { copy = w.session().log(); });
    return copy;
}

} // namespace pf
