#pragma once

#include <functional>
#include <mutex>
#include <utility>
#include <vector>

namespace pf {

// Closures handed from one thread to the other under a std::mutex. Qt's queued calls
// synchronise inside Qt, which is not built with ThreadSanitizer, so data carried in
// them (a lambda's captures, a signal's arguments) looks unsynchronised to it; data
// carried here is ordered by a lock it sees. Qt only wakes the receiver, with a call
// that carries nothing.
template <typename... Args> class CrossThreadQueue {
  public:
    using Task = std::function<void(Args...)>;

    // True when the queue was empty: the caller then wakes the receiver, once per batch.
    bool post(Task task) {
        std::lock_guard lock(mutex_);
        tasks_.push_back(std::move(task));
        return tasks_.size() == 1;
    }

    std::vector<Task> takeAll() {
        std::lock_guard lock(mutex_);
        return std::exchange(tasks_, {});
    }

  private:
    std::mutex mutex_;
    std::vector<Task> tasks_;
};

} // namespace pf
