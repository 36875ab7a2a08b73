#pragma once

#include "CrossThreadQueue.h"

#include <QMetaObject>
#include <condition_variable>
#include <mutex>

namespace pf {

class SimulationWorker;

// What the GUI thread and the simulation thread share besides Qt's wake-ups: the
// commands the GUI queued for the worker, and the worker's last word as it goes.
class SimulationChannel {
  public:
    CrossThreadQueue<SimulationWorker&> commands;
    // The GUI's wake-up of the worker; the worker drops it as it goes, on its own
    // thread, so that nothing of it is touched after the GUI side may be gone.
    QMetaObject::Connection wake;

    // Called last by the worker's destructor, on the simulation thread.
    void markWorkerGone() {
        std::lock_guard lock(mutex_);
        workerGone_ = true;
        changed_.notify_all();
    }
    // QThread::wait synchronises inside Qt, where ThreadSanitizer cannot see it; this
    // lock it can.
    void waitForWorkerGone() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [this] { return workerGone_; });
    }

  private:
    std::mutex mutex_;
    std::condition_variable changed_;
    bool workerGone_ = false;
};

} // namespace pf
