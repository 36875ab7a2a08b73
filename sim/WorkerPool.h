#pragma once

#include "Types.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace pf {

// Threads that share a loop over [0, count) in contiguous chunks, the caller's thread
// among them. The step's passes use it only where each element's result is worked out
// on its own, in a fixed order (VertexStars), so a step gives the same bits on any
// number of threads: the threads change who computes, never what. Chunk c always goes to
// thread c mod threads(), so a thread works on the same stretch of the sheet from one
// pass and one step to the next and finds it in its own cache: handing chunks out to
// whichever thread came free first measured slower on this machine (side by side at
// 100k springs: 275-288 against 292-297 steps/s on two threads), likely from the data moving
// between the cores' caches.
class WorkerPool {
  public:
    // Fewer elements than this per thread are not worth waking a thread for: a part
    // of the sheet's smallest loops takes less than the wake-up (microseconds).
    static constexpr Index kMinPerPart = 2048;
    // Chunks per thread for loops whose costly elements bunch up in one stretch of the
    // range (forChunks): taken in turn, each thread gets some of the bunch.
    static constexpr int kChunksPerThread = 8;

    explicit WorkerPool(int threads = 1);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int threads() const { return threads_; }
    // The threads this machine offers (1 to 64).
    static int machineThreads();
    // Clamps to [1, 64]; 0 or less means machineThreads(). The threads start when a loop
    // first needs them: a pool whose loops are all small (a small sheet's) starts none.
    void setThreads(int threads);

    // A pool of one thread that never starts any: for callers without a pool.
    static WorkerPool& serial();

    // How many threads a loop of `count` elements is shared among (at most threads()).
    int partsFor(Index count) const;

    // Calls work(begin, end) on contiguous ranges that cover [0, count) once, one per
    // thread, and returns when all are done. `work` must not throw.
    template <class Work> void forRanges(Index count, Work&& work) {
        const int parts = partsFor(count);
        if (parts <= 1) {
            if (count > 0) work(Index{0}, count);
            return;
        }
        auto ranges = [&](int, Index begin, Index end) { work(begin, end); };
        dispatch(count, parts, ranges);
    }

    // Splits [0, count) into `chunks` contiguous chunks (chunk c from count·c/chunks) and
    // calls work(chunk, begin, end) once for each non-empty one, the threads taking them
    // in turn: for a loop that writes per-chunk results to be read in chunk order
    // afterwards. `work` must not throw.
    template <class Work> void forChunks(Index count, int chunks, Work&& work) {
        if (partsFor(count) <= 1) {
            for (int c = 0; c < chunks; ++c) {
                const Index begin = chunkBegin(count, chunks, c);
                const Index end = chunkBegin(count, chunks, c + 1);
                if (begin < end) work(c, begin, end);
            }
            return;
        }
        dispatch(count, chunks, work);
    }

  private:
    using Trampoline = void (*)(void*, int, Index, Index);
    template <class Work> void dispatch(Index count, int chunks, Work& work) {
        run(count, chunks, &work, [](void* w, int chunk, Index begin, Index end) {
            (*static_cast<Work*>(w))(chunk, begin, end);
        });
    }
    void run(Index count, int chunks, void* work, Trampoline call);
    // Does this thread's chunks of the current job.
    void takeChunks(int thread);
    void workerLoop(int thread, std::uint64_t seen);
    void stop();
    static Index chunkBegin(Index count, int chunks, int chunk) {
        return static_cast<Index>(static_cast<std::int64_t>(count) * chunk / chunks);
    }

    void startWorkers();

    int threads_ = 1;
    std::vector<std::thread> workers_;
    // A part takes tens of microseconds to a few milliseconds and the step's serial work
    // between parts less, so waiting threads spin for a while before they sleep: waking a
    // sleeping thread costs a system call on each side, which measured a tenth of the
    // step on two threads.
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<int> pending_{0}; // workers yet to finish the current generation
    std::atomic<bool> stopping_{false};
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::chrono::microseconds spin_{0};     // how long a waiting thread spins before it sleeps
    std::atomic<int> sleepers_{0};          // workers asleep on wake_
    std::atomic<bool> callerAsleep_{false}; // the caller asleep on done_
    // The job of the current generation: written before generation_ is raised, read by
    // every worker after it sees the raise, and not written again until all have finished.
    Index count_ = 0;
    int chunks_ = 0;
    void* work_ = nullptr;
    Trampoline call_ = nullptr;
};

} // namespace pf
