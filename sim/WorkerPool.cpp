#include "WorkerPool.h"

#include <algorithm>
#include <chrono>

namespace pf {

namespace {

// How long a waiting thread spins before it sleeps.
constexpr auto kSpin = std::chrono::microseconds(100);

// Spins until done() or `spin` has passed; returns done(). It gives up its core between
// rounds, so that a thread with work that shares the core is not kept waiting.
template <class Done> bool spinUntil(Done done, std::chrono::microseconds spin) {
    const auto until = std::chrono::steady_clock::now() + spin;
    for (;;) {
        for (int k = 0; k < 64; ++k) {
            if (done()) return true;
#if defined(__x86_64__) || defined(__i386__)
            __builtin_ia32_pause();
#endif
        }
        if (std::chrono::steady_clock::now() > until) return done();
        std::this_thread::yield();
    }
}

} // namespace

WorkerPool::WorkerPool(int threads) {
    setThreads(threads);
}

WorkerPool::~WorkerPool() {
    stop();
}

int WorkerPool::machineThreads() {
    return std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 64);
}

WorkerPool& WorkerPool::serial() {
    static WorkerPool one(1);
    return one;
}

void WorkerPool::setThreads(int threads) {
    const int wanted = std::clamp(threads > 0 ? threads : machineThreads(), 1, 64);
    if (wanted == threads_) return;
    stop();
    threads_ = wanted;
}

void WorkerPool::startWorkers() {
    stopping_ = false;
    // More threads than cores: a spinning thread would hold a core from one with work.
    spin_ = threads_ <= machineThreads() ? kSpin : std::chrono::microseconds(0);
    for (int part = 1; part < threads_; ++part)
        workers_.emplace_back([this, part, now = generation_.load()] { workerLoop(part, now); });
}

void WorkerPool::stop() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
    workers_.clear();
}

int WorkerPool::partsFor(Index count) const {
    const Index byGrain = count / kMinPerPart;
    return static_cast<int>(std::clamp<Index>(byGrain, 1, threads()));
}

void WorkerPool::takeChunks(int thread) {
    for (int c = thread; c < chunks_; c += threads()) {
        const Index begin = chunkBegin(count_, chunks_, c),
                    end = chunkBegin(count_, chunks_, c + 1);
        if (begin < end) call_(work_, c, begin, end);
    }
}

void WorkerPool::run(Index count, int chunks, void* work, Trampoline call) {
    if (workers_.empty()) startWorkers();
    count_ = count;
    chunks_ = chunks;
    work_ = work;
    call_ = call;
    pending_ = threads() - 1;
    ++generation_;
    // A worker that went to sleep before the raise is woken; one that goes after it
    // sees the raise under the lock (both sides are sequentially consistent).
    if (sleepers_ > 0) {
        std::lock_guard lock(mutex_);
        wake_.notify_all();
    }
    takeChunks(0);
    if (spinUntil([this] { return pending_ == 0; }, spin_)) return;
    std::unique_lock lock(mutex_);
    callerAsleep_ = true;
    done_.wait(lock, [this] { return pending_ == 0; });
    callerAsleep_ = false;
}

void WorkerPool::workerLoop(int thread, std::uint64_t seen) {
    for (;;) {
        const auto raised = [&] { return stopping_ || generation_ != seen; };
        if (!spinUntil(raised, spin_)) {
            std::unique_lock lock(mutex_);
            ++sleepers_;
            wake_.wait(lock, raised);
            --sleepers_;
        }
        if (stopping_) return;
        seen = generation_;
        takeChunks(thread);
        if (--pending_ == 0 && callerAsleep_) {
            std::lock_guard lock(mutex_);
            done_.notify_one();
        }
    }
}

} // namespace pf
