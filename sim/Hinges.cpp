#include "Hinges.h"

#include <cmath>

namespace pf {

bool canHinge(const Sheet& sheet, Index spring) {
    const auto& S = sheet.springs;
    return S.kind[spring] == SpringKind::Structural && !S.hinged[spring] &&
           S.faces[spring][0] != kNone && S.faces[spring][1] != kNone;
}

Index insertHinge(Sheet& sheet, Index spring, double rest, std::int64_t step) {
    auto& S = sheet.springs;
    const Index r = sheet.oppositeVertex(S.faces[spring][0], S.a[spring], S.b[spring]);
    const Index l = sheet.oppositeVertex(S.faces[spring][1], S.a[spring], S.b[spring]);
    sheet.paper.meshChanged();
    const Index hinge = sheet.addSpring(r, l, rest, SpringKind::Hinge, false);
    DamageEvent ev;
    ev.kind = EventKind::Hinge;
    ev.step = step;
    ev.edge = spring;
    ev.springs = {hinge, kNone, kNone, kNone};
    sheet.events.push_back(ev);
    const Index event = static_cast<Index>(sheet.events.size()) - 1;
    S.event[hinge] = event;
    S.hinged[spring] = 1;
    return event;
}

int runHingePass(Sheet& sheet, const SimParams& params, std::int64_t step, HingeScratch& scratch,
                 const StepWorkers& workers) {
    WorkerPool& pool = workers.poolOrSerial();
    const double threshold2 = params.hingeThreshold * params.hingeThreshold;
    // An insertion changes nothing another edge's test reads (it marks its own edge and
    // appends a spring), so all edges can be tested first. The structural edges are the
    // sheet's first springs, so the threads take small chunks in turn.
    const int chunks = WorkerPool::kChunksPerThread * pool.threads();
    scratch.found.resize(static_cast<std::size_t>(chunks));
    for (auto& chunk : scratch.found) chunk.clear();
    pool.forChunks(sheet.springs.size(), chunks, [&](int chunk, Index begin, Index end) {
        auto& found = scratch.found[static_cast<std::size_t>(chunk)];
        const auto& S = sheet.springs;
        const auto& V = sheet.verts;
        for (Index s = begin; s < end; ++s) {
            if (!canHinge(sheet, s)) continue;
            const Index r = sheet.oppositeVertex(S.faces[s][0], S.a[s], S.b[s]);
            const Index l = sheet.oppositeVertex(S.faces[s][1], S.a[s], S.b[s]);
            const double d2 = (V.x[r] - V.x[l]).squaredNorm();
            const double rest2 = (V.X[r] - V.X[l]).squaredNorm();
            // r on l (pins can hold them there) leaves a spring no direction and no
            // positive rest length: the fold gets its hinge once they part.
            if (d2 > 0.0 && d2 < threshold2 * rest2) found.push_back({s, std::sqrt(d2)});
        }
    });
    int inserted = 0;
    for (const auto& chunk : scratch.found)
        for (const HingeScratch::Found& f : chunk) {
            insertHinge(sheet, f.spring, f.rest, step);
            ++inserted;
        }
    return inserted;
}

int runHingePass(Sheet& sheet, const SimParams& params, std::int64_t step) {
    HingeScratch scratch;
    return runHingePass(sheet, params, step, scratch, {});
}

} // namespace pf
