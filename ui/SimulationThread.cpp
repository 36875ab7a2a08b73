#include "SimulationThread.h"

#include "SimulationWorker.h"

#include <QMetaObject>

namespace pf {

SimulationThread::SimulationThread(World initial, QObject* parent) : QObject(parent) {
    qRegisterMetaType<std::shared_ptr<const World>>("std::shared_ptr<const World>");
    qRegisterMetaType<pf::SimParams>("pf::SimParams");
    worker_ = new SimulationWorker(std::move(initial), this);
    worker_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    thread_.setObjectName(QStringLiteral("simulation"));
    thread_.start();
    QMetaObject::invokeMethod(
        worker_, [w = worker_] { w->start(); }, Qt::QueuedConnection);
}

SimulationThread::~SimulationThread() {
    thread_.quit();
    thread_.wait();
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
    if (!notifyPending_.exchange(true))
        QMetaObject::invokeMethod(
            this,
            [this] {
                notifyPending_ = false;
                emit snapshotReady();
            },
            Qt::QueuedConnection);
}

#define PF_POST(call)                                                                              \
    QMetaObject::invokeMethod(                                                                     \
        worker_, [=, w = worker_] { w->call; }, Qt::QueuedConnection)

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

#undef PF_POST

void SimulationThread::sync() {
    QMetaObject::invokeMethod(
        worker_, [] {}, Qt::BlockingQueuedConnection);
}

} // namespace pf
