#include "SelfContact.h"

#include "TriangleGeometry.h"

#include <algorithm>
#include <cmath>

namespace pf {

namespace {

// A triangle whose box covers more cells than this (32 a side: a triangle some 20 times
// the mesh's mean edge across) has blown up; it is left out.
constexpr std::int64_t kMaxCellsPerBox = 32768;
// How far out of a triangle (in its barycentric coordinates) a vertex's foot may lie and
// still be held by it: a foot on the edge between two triangles of a layer is held by
// both (the pairs are found by distance, so both are there).
constexpr double kOnTriangle = 0.02;

double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + s * ab)).norm();
}

std::uint64_t cellKey(std::int64_t i, std::int64_t j, std::int64_t k) {
    constexpr std::uint64_t mask = (1u << 21) - 1;
    return ((static_cast<std::uint64_t>(i) & mask) << 42) |
           ((static_cast<std::uint64_t>(j) & mask) << 21) | (static_cast<std::uint64_t>(k) & mask);
}

std::size_t slotOf(std::uint64_t key, std::size_t slots) {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & (slots - 1);
}

} // namespace

void SelfContact::find(const Sheet& sheet, const std::vector<double>& inverseMass, double thickness,
                       const std::vector<double>& allowance, double apart, int bucketCells) {
    pairs_.clear();
    cells_.clear();
    thickness_ = thickness;
    const auto& X = sheet.verts.x;
    const auto& M = sheet.verts.X;
    const Index nv = sheet.verts.size();
    const Index nt = sheet.triangleCount();
    if (nt == 0 || allowance.size() != X.size()) return;

    // The free vertices hashed by the cells of their boxes (each as far round it as it
    // may move); each triangle looks in the cells its own box, grown by the thickness and
    // as far as its corners may move, covers.
    // Cells of the mesh's size, or a quarter of the widest allowance (pins that carry
    // the paper included): a vertex's box then spans at most nine cells a side, and a
    // triangle's at most nine more than its own width (with the mesh's size alone, a
    // vertex at 1 m/s on a sheet of 1 mm edges covered about 7,000 cells).
    double edgeSum = 0.0;
    for (const Triangle& t : sheet.tris) edgeSum += (X[t.v[0]] - X[t.v[1]]).norm();
    double widest = 0.0;
    for (Index v = 0; v < nv; ++v) widest = std::max(widest, allowance[v]);
    const double cell = std::max(edgeSum / nt, 0.25 * (widest + thickness));
    if (!std::isfinite(cell) || !(cell > 0.0)) return;
    // (Offset by half a cell, so that paper lying on the desk at y = 0 lies in one layer
    // of cells, not astride two.)
    const auto cellOf = [&](double c) {
        return static_cast<std::int64_t>(std::floor(c / cell + 0.5));
    };
    // A box's cells, or none if it is not finite or has blown up.
    const auto cellsOf = [&](const Vec3& lo, const Vec3& hi, CellRange& range) {
        if (!lo.allFinite() || !hi.allFinite()) return false;
        for (int axis = 0; axis < 3; ++axis) {
            range.lo[axis] = cellOf(lo[axis]);
            range.hi[axis] = cellOf(hi[axis]);
        }
        return (range.hi[0] - range.lo[0] + 1) * (range.hi[1] - range.lo[1] + 1) *
                   (range.hi[2] - range.lo[2] + 1) <=
               kMaxCellsPerBox;
    };
    // Which pairs are tried is decided in these cells, and so is their order: a
    // triangle's pairs come in the order of the first cell each vertex shares with it
    // (by x, then y, then z, as the triangle's cells were once walked), then by vertex.
    // The hash itself has buckets of `group` cells a side. When the vertices' boxes
    // span many cells (paper that swings fast), a triangle and a vertex shared up to
    // hundreds of cells, and walking the same vertex again in each took 40 % of a
    // swinging sheet's step; buckets about as wide as the widest allowance hold each box
    // in two or three a side. The buckets decide only where to look, so the pairs are the
    // same, in the same order, for any size of bucket (test_self_contact).
    const std::int64_t group =
        bucketCells < 0   ? 1
        : bucketCells > 0 ? bucketCells
                          : std::max<std::int64_t>(1, static_cast<std::int64_t>(widest / cell));
    const auto bucketOf = [group](std::int64_t c) {
        return c >= 0 ? c / group : -((-c + group - 1) / group);
    };
    const auto eachBucket = [&](const CellRange& range, const auto& visit) {
        const std::int64_t i0 = bucketOf(range.lo[0]), i1 = bucketOf(range.hi[0]);
        const std::int64_t j0 = bucketOf(range.lo[1]), j1 = bucketOf(range.hi[1]);
        const std::int64_t k0 = bucketOf(range.lo[2]), k1 = bucketOf(range.hi[2]);
        for (std::int64_t i = i0; i <= i1; ++i)
            for (std::int64_t j = j0; j <= j1; ++j)
                for (std::int64_t k = k0; k <= k1; ++k) visit(cellKey(i, j, k));
    };
    vertexCells_.resize(static_cast<std::size_t>(nv));
    for (Index v = 0; v < nv; ++v)
        if (inverseMass[v] != 0.0 &&
            cellsOf(X[v].array() - allowance[v], X[v].array() + allowance[v], vertexCells_[v]))
            eachBucket(vertexCells_[v], [&](std::uint64_t key) { cells_.emplace_back(key, v); });
    std::sort(cells_.begin(), cells_.end());
    // Each occupied bucket's run of vertices, by open addressing (a binary search per
    // bucket a triangle covers took most of the search).
    std::size_t slots = 16;
    while (slots < 2 * cells_.size()) slots *= 2;
    slots_.assign(slots, Slot{});
    for (std::size_t r = 0; r < cells_.size();) {
        std::size_t e = r;
        while (e < cells_.size() && cells_[e].first == cells_[r].first) ++e;
        std::size_t h = slotOf(cells_[r].first, slots);
        while (slots_[h].end != 0) h = (h + 1) & (slots - 1);
        slots_[h] = {cells_[r].first, static_cast<Index>(r), static_cast<Index>(e)};
        r = e;
    }
    const auto run = [&](std::uint64_t key) -> const Slot* {
        for (std::size_t h = slotOf(key, slots_.size()); slots_[h].end != 0;
             h = (h + 1) & (slots_.size() - 1))
            if (slots_[h].key == key) return &slots_[h];
        return nullptr;
    };

    // The triangles round each vertex: a triangle with a corner of one of them is the
    // vertex's own paper (its ring bends through a crease), not another layer.
    ringStart_.assign(static_cast<std::size_t>(nv) + 1, 0);
    for (const Triangle& t : sheet.tris)
        for (Index v : t.v) ++ringStart_[v + 1];
    for (Index i = 0; i < nv; ++i) ringStart_[i + 1] += ringStart_[i];
    ring_.resize(static_cast<std::size_t>(ringStart_[nv]));
    ringFill_.assign(ringStart_.begin(), ringStart_.end() - 1);
    for (Index t = 0; t < nt; ++t)
        for (Index v : sheet.tris[t].v) ring_[ringFill_[v]++] = t;
    const auto near = [&](Index v, const Triangle& other) {
        for (Index r = ringStart_[v]; r < ringStart_[v + 1]; ++r)
            for (Index corner : sheet.tris[ring_[r]].v)
                if (corner == other.v[0] || corner == other.v[1] || corner == other.v[2])
                    return true;
        return false;
    };

    // A vertex in several cells a triangle covers is tried once for it.
    seenBy_.assign(static_cast<std::size_t>(nv), kNone);
    for (Index ti = 0; ti < nt; ++ti) {
        const Triangle& t = sheet.tris[ti];
        const Vec3 &a = X[t.v[0]], &b = X[t.v[1]], &c = X[t.v[2]];
        const Vec3 ab = b - a, ac = c - a;
        Vec3 n = ab.cross(ac);
        const double len = n.norm();
        if (!(len > 0.0) || !std::isfinite(len)) continue;
        n /= len;
        // The foot of a point on the plane, in barycentric coordinates, from two dot
        // products (Ericson 3.4): most candidates are the triangle's own layer beside it,
        // and this is all they cost.
        const double d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac);
        const double det = d00 * d11 - d01 * d01;
        if (!(det > 0.0)) continue; // a sliver rounded flat: no plane to be on a side of
        const double inverseDet = 1.0 / det;
        const double moves = std::max({allowance[t.v[0]], allowance[t.v[1]], allowance[t.v[2]]});
        const Vec3 lo = a.cwiseMin(b).cwiseMin(c).array() - (thickness + moves);
        const Vec3 hi = a.cwiseMax(b).cwiseMax(c).array() + (thickness + moves);
        CellRange range;
        if (!cellsOf(lo, hi, range)) continue;
        found_.clear();
        eachBucket(range, [&](std::uint64_t key) {
            const Slot* slot = run(key);
            if (!slot) return;
            for (Index r = slot->begin; r < slot->end; ++r) {
                const Index v = cells_[r].second;
                if (seenBy_[v] == ti) continue;
                seenBy_[v] = ti;
                if (v == t.v[0] || v == t.v[1] || v == t.v[2]) continue;
                // The first cell the vertex's box shares with the triangle's, if any.
                const CellRange& box = vertexCells_[v];
                std::array<std::int64_t, 3> first;
                bool shares = true;
                for (int axis = 0; axis < 3; ++axis) {
                    first[axis] = std::max(range.lo[axis], box.lo[axis]);
                    shares = shares && first[axis] <= std::min(range.hi[axis], box.hi[axis]);
                }
                if (!shares) continue;
                // Paper this far apart now cannot touch before either has moved more
                // than it may.
                const double reach = thickness + moves + allowance[v];
                const Vec3 ap = X[v] - a;
                const double dn = ap.dot(n);
                if (!(std::abs(dn) < reach)) continue;
                const double d20 = ap.dot(ab), d21 = ap.dot(ac);
                const double fv = (d11 * d20 - d01 * d21) * inverseDet;
                const double fw = (d00 * d21 - d01 * d20) * inverseDet;
                const bool footOn = std::min({1.0 - fv - fw, fv, fw}) >= -kOnTriangle;
                // Paper in the triangle's plane beside it is the same layer (a flat
                // sheet's every vertex is within reach of the triangles round its ring),
                // unless its foot is on the triangle already.
                if (std::abs(dn) < thickness && !footOn) continue;
                if (!footOn) {
                    const Vec3 bary = closestPointBarycentric(a, b, c, X[v]);
                    if (!((bary[0] * a + bary[1] * b + bary[2] * c - X[v]).squaredNorm() <
                          reach * reach))
                        continue;
                }
                if (near(v, t)) continue;
                if (std::min({segmentDistance(M[v], M[t.v[0]], M[t.v[1]]),
                              segmentDistance(M[v], M[t.v[1]], M[t.v[2]]),
                              segmentDistance(M[v], M[t.v[2]], M[t.v[0]])}) < apart)
                    continue;
                found_.push_back({{first[0], first[1], first[2], v},
                                  {v, ti, t.v, dn >= 0.0 ? 1.0 : -1.0, moves + allowance[v]}});
            }
        });
        // (With buckets of one cell the walk finds them in that order already; a negative
        // bucketCells keeps the walk's own order, for the test that compares the two.)
        if (bucketCells >= 0)
            std::sort(found_.begin(), found_.end(),
                      [](const Found& p, const Found& q) { return p.order < q.order; });
        for (const Found& f : found_) pairs_.push_back(f.pair);
    }
}

void SelfContact::resolve(std::vector<Vec3>& x, const std::vector<Vec3>& previous,
                          const std::vector<double>& inverseMass, double staticFriction,
                          double kineticFriction, bool withFriction, double maxSeparation) {
    if (pairs_.empty()) return;
    const double t = thickness_;
    // The pairs come triangle by triangle, some twenty to a triangle, and few of them
    // move anything: a triangle's normal is worked out once for its run of pairs and
    // again only if one of its corners has moved since. Worked out again, it is the same
    // arithmetic on the same positions, so the result is the same to the bit as working
    // it out for every pair (which was 35 % of a swinging sheet's step).
    // (The clock runs on from call to call, so older moves are all earlier than this
    // call's normals and the stamps need no clearing.)
    if (movedAt_.size() != x.size()) movedAt_.assign(x.size(), 0);
    std::uint64_t lastMove = 0, computedAt = 0;
    Index normalOf = kNone;
    Vec3 unitNormal[2]; // toward the side a vertex below / above the triangle belongs on
    bool flat = true;
    for (const Pair& p : pairs_) {
        const auto& c = p.corners;
        const bool current =
            p.triangle == normalOf &&
            (lastMove < computedAt || (movedAt_[c[0]] < computedAt && movedAt_[c[1]] < computedAt &&
                                       movedAt_[c[2]] < computedAt));
        if (!current) {
            const Vec3 raw = (x[c[1]] - x[c[0]]).cross(x[c[2]] - x[c[0]]);
            const double len = raw.norm();
            flat = !(len > 0.0);
            // (-1 / len is -(1 / len), bit for bit: the same as side / len for either side.)
            unitNormal[0] = raw * (-1.0 / len);
            unitNormal[1] = raw * (1.0 / len);
            normalOf = p.triangle;
            computedAt = ++clock_;
        }
        if (flat) continue;
        const Vec3& n = unitNormal[p.side > 0.0 ? 1 : 0]; // toward the vertex's side
        // The gap to the triangle's plane, where the vertex's foot is on the triangle
        // (most pairs are apart: this is all they cost).
        const double gap = (x[p.vertex] - x[c[0]]).dot(n);
        if (!(gap < t) || !(gap > -p.depth)) continue;
        // Paper that began this correction inside the thickness (the constraints press
        // it there) is pushed out only so fast: pushed out at once, the light vertices a
        // break inserts, caught between layers, flew off at tens of metres a second.
        const double before = (previous[p.vertex] - previous[c[0]]).dot(n);
        const double target = std::min(t, std::max(before, gap) + maxSeparation);
        if (!(gap < target)) continue;
        Vec3 b;
        if (!footBarycentric(x[c[0]], x[c[1]], x[c[2]], x[p.vertex], b) ||
            b.minCoeff() < -kOnTriangle)
            continue;
        b = b.cwiseMax(0.0);
        b /= b.sum();
        const double wv = inverseMass[p.vertex];
        const double wsum = wv + inverseMass[c[0]] * b[0] * b[0] + inverseMass[c[1]] * b[1] * b[1] +
                            inverseMass[c[2]] * b[2] * b[2];
        if (!(wsum > 0.0)) continue;
        const double push = target - gap;
        // Moving the vertex by w_v / Σ and each corner by w_k b_k / Σ of a correction
        // moves the vertex relative to its foot by exactly the correction.
        Vec3 move = push * n;
        if (withFriction) {
            const Vec3 rel =
                (x[p.vertex] - previous[p.vertex]) -
                (b[0] * (x[c[0]] - previous[c[0]]) + b[1] * (x[c[1]] - previous[c[1]]) +
                 b[2] * (x[c[2]] - previous[c[2]]));
            const Vec3 slip = rel - rel.dot(n) * n;
            const double s = slip.norm();
            if (s <= staticFriction * push)
                move -= slip;
            else if (s > 0.0)
                move -= slip * std::min(1.0, kineticFriction * push / s);
        }
        x[p.vertex] += (wv / wsum) * move;
        for (int k = 0; k < 3; ++k) x[c[k]] -= (inverseMass[c[k]] * b[k] / wsum) * move;
        lastMove = ++clock_;
        movedAt_[p.vertex] = movedAt_[c[0]] = movedAt_[c[1]] = movedAt_[c[2]] = lastMove;
    }
}

std::size_t SelfContact::crossed(const std::vector<Vec3>& x) const {
    std::size_t n = 0;
    for (const Pair& p : pairs_) {
        const auto& c = p.corners;
        const Vec3 normal = (x[c[1]] - x[c[0]]).cross(x[c[2]] - x[c[0]]);
        Vec3 b;
        if (!footBarycentric(x[c[0]], x[c[1]], x[c[2]], x[p.vertex], b) ||
            b.minCoeff() < -kOnTriangle)
            continue;
        const double gap = p.side * (x[p.vertex] - x[c[0]]).dot(normal) / normal.norm();
        if (gap < 0.0 && gap > -p.depth) ++n;
    }
    return n;
}

} // namespace pf
