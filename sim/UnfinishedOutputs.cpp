#include "UnfinishedOutputs.h"

#include <atomic>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace pf {

namespace {

// A signal handler may only read lock-free atomics and fixed memory, so the names live
// in a fixed table: writes run on a handful of threads at most.
constexpr int kSlots = 16;
constexpr std::size_t kMaxPath = 4096;
enum SlotState : int { Free = 0, Filling = 1, Ready = 2 };
struct Slot {
    std::atomic<int> state{Free};
    char path[kMaxPath]{};
};
Slot table[kSlots];
static_assert(std::atomic<int>::is_always_lock_free);

void removeAndEnd(int signal) {
    for (Slot& s : table)
        if (s.state.load() == Ready) ::unlink(s.path);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

} // namespace

UnfinishedOutput::UnfinishedOutput(const QByteArray& path) {
    if (path.size() + 1 > qsizetype(kMaxPath)) return;
    for (int k = 0; k < kSlots; ++k) {
        int expected = Free;
        if (!table[k].state.compare_exchange_strong(expected, Filling)) continue;
        std::memcpy(table[k].path, path.constData(), std::size_t(path.size()) + 1);
        table[k].state.store(Ready);
        slot_ = k;
        return;
    }
}

UnfinishedOutput::~UnfinishedOutput() {
    if (slot_ >= 0) table[slot_].state.store(Free);
}

void removeUnfinishedOutputsOnSignals() {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
        struct sigaction now {};
        if (sigaction(signal, nullptr, &now) != 0 || now.sa_handler == SIG_IGN) continue;
        struct sigaction handler {};
        handler.sa_handler = removeAndEnd;
        sigemptyset(&handler.sa_mask);
        sigaction(signal, &handler, nullptr);
    }
}

} // namespace pf
