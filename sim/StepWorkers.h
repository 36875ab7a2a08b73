#pragma once

#include "VertexStars.h"
#include "WorkerPool.h"

namespace pf {

// The threads and the vertex stars a simulation lends the passes of its step. The stars
// are current for the sheet as the step began. Without them a pass runs on one thread.
struct StepWorkers {
    WorkerPool* pool = nullptr;
    const VertexStars* stars = nullptr;

    WorkerPool& poolOrSerial() const { return pool ? *pool : WorkerPool::serial(); }
};

} // namespace pf
