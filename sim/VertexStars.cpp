#include "VertexStars.h"

#include <algorithm>
#include <atomic>

namespace pf {

namespace {

// Room left in each star for springs appended later (hinges, mostly: a crumpling sheet
// gains some every step), so that appending does not rebuild every star.
constexpr Index kSlack = 4;

// Whether the first `count` elements of `now` equal `built`, compared on the pool's threads.
template <class T>
bool samePrefix(const std::vector<T>& now, const std::vector<T>& built, WorkerPool& pool) {
    if (now.size() < built.size()) return false;
    std::atomic<bool> differs{false};
    pool.forRanges(static_cast<Index>(built.size()), [&](Index begin, Index end) {
        if (!std::equal(built.begin() + begin, built.begin() + end, now.begin() + begin))
            differs = true;
    });
    return !differs;
}

} // namespace

bool VertexStars::appendSpring(Index s, Index a, Index b) {
    for (int end = 0; end < 2; ++end) {
        const Index v = end == 0 ? a : b;
        if (springStart_[v] + springUsed_[v] == springStart_[v + 1]) return false;
        springs_[springStart_[v] + springUsed_[v]++] = 2 * s + end;
    }
    return true;
}

bool VertexStars::refresh(const Sheet& sheet, WorkerPool& pool) {
    const Index nv = sheet.verts.size();
    const auto& S = sheet.springs;
    if (nv == vertexCount() && sheet.tris.size() == builtTris_.size() &&
        samePrefix(S.a, builtA_, pool) && samePrefix(S.b, builtB_, pool) &&
        samePrefix(sheet.tris, builtTris_, pool)) {
        if (S.a.size() == builtA_.size()) return false;
        // Only springs were appended: each goes at the end of its ends' stars, in order.
        bool fits = true;
        for (Index s = static_cast<Index>(builtA_.size()); s < S.size() && fits; ++s)
            fits = appendSpring(s, S.a[s], S.b[s]);
        if (fits) {
            builtA_.insert(builtA_.end(), S.a.begin() + static_cast<std::ptrdiff_t>(builtA_.size()),
                           S.a.end());
            builtB_.insert(builtB_.end(), S.b.begin() + static_cast<std::ptrdiff_t>(builtB_.size()),
                           S.b.end());
            return true;
        }
    }
    rebuild(sheet);
    return true;
}

void VertexStars::rebuild(const Sheet& sheet) {
    const Index nv = sheet.verts.size();
    const auto& S = sheet.springs;
    // Springs: counted per vertex, room for kSlack more, filled in ascending order.
    springUsed_.assign(static_cast<std::size_t>(nv), 0);
    for (Index s = 0; s < S.size(); ++s) {
        ++springUsed_[S.a[s]];
        ++springUsed_[S.b[s]];
    }
    springStart_.assign(static_cast<std::size_t>(nv) + 1, 0);
    for (Index v = 0; v < nv; ++v) springStart_[v + 1] = springStart_[v] + springUsed_[v] + kSlack;
    springs_.resize(static_cast<std::size_t>(springStart_[nv]));
    std::fill(springUsed_.begin(), springUsed_.end(), 0);
    for (Index s = 0; s < S.size(); ++s) appendSpring(s, S.a[s], S.b[s]);

    // Triangles: packed (any change to them rebuilds).
    triangleStart_.assign(static_cast<std::size_t>(nv) + 1, 0);
    for (const Triangle& t : sheet.tris)
        for (Index w : t.v) ++triangleStart_[static_cast<std::size_t>(w) + 1];
    for (Index v = 0; v < nv; ++v) triangleStart_[v + 1] += triangleStart_[v];
    triangles_.resize(static_cast<std::size_t>(triangleStart_[nv]));
    std::vector<Index> next(triangleStart_.begin(), triangleStart_.end() - 1);
    for (Index t = 0; t < sheet.triangleCount(); ++t)
        for (Index w : sheet.tris[t].v) triangles_[next[w]++] = t;

    builtA_ = S.a;
    builtB_ = S.b;
    builtTris_ = sheet.tris;
}

} // namespace pf
