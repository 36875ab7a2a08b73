#include "Breaking.h"

#include "Integrator.h"
#include "Normals.h"
#include "TopologyEdit.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pf {

double breakProbability(double l, double l0, double lrl, double nij, double nrl, double phi) {
    if (!(l < l0) || !(l0 > 0.0)) return 0.0;
    const double contraction = 1.0 - l / l0;
    const double lengthRatio = l / (l + lrl);
    const double curvature = (1.0 - phi * nij) * (1.0 + phi * nrl) / 4.0;
    return contraction * lengthRatio * curvature;
}

double breakProbabilityForGrowth(double P, double growth, double referenceGrowth) {
    if (P <= 0.0 || !(growth > 0.0)) return 0.0;
    if (P >= 1.0) return 1.0;
    // 1 - (1 - P)^(growth/ref), with log1p/expm1 to stay accurate for tiny P and growth.
    return -std::expm1((growth / referenceGrowth) * std::log1p(-P));
}

namespace {

// What Eq. 10 reads of an edge (docs/model.md, "What a stiff paper's break reads"):
// its chord, and its contraction with the length l that goes with it.
struct EdgeLoad {
    double chord = 0.0;
    double contraction = 0.0;
    double length = 0.0;
};

// The paper reads the chord: its soft springs shorten where the paper buckles finer than
// the mesh. Paper with its real stretch stiffness (xpbd) keeps every chord at its length
// and bends instead, so there the contraction is read on the arc: paper whose normals
// turn by θ between i and j, and whose arc between them is as long as the chord says,
// spans only sin(θ/2)/(θ/2) of it. A flat edge reads the same either way.
struct ContractionReading {
    const std::vector<Vec3>& normals;
    bool onTheArc;

    EdgeLoad of(const Sheet& sheet, Index spring) const {
        const auto& S = sheet.springs;
        const Index i = S.a[spring], j = S.b[spring];
        EdgeLoad e;
        e.chord = (sheet.verts.x[i] - sheet.verts.x[j]).norm();
        e.contraction = 1.0 - e.chord / S.rest[spring];
        e.length = e.chord;
        if (!onTheArc) return e;
        const double turn = std::acos(std::clamp(normals[i].dot(normals[j]), -1.0, 1.0));
        const double half = 0.5 * turn;
        const double spanned = half > 1e-8 ? std::sin(half) / half : 1.0;
        e.contraction = 1.0 - (1.0 - e.contraction) * spanned;
        e.length = S.rest[spring] * (1.0 - e.contraction);
        return e;
    }
};

ContractionReading readingFor(const SimParams& params, const std::vector<Vec3>& normals) {
    return {normals, keepsEdgeLengths(params.integrator)};
}

} // namespace

double breakOffset(double l, double l0, double psi) {
    if (!(l < l0)) return 0.0;
    return 0.5 * psi * std::sqrt(l0 * l0 - l * l);
}

namespace {

double materialArea(const Sheet& sheet, const Triangle& t) {
    const auto& X = sheet.verts.X;
    const Vec2 a = X[t.v[1]] - X[t.v[0]];
    const Vec2 b = X[t.v[2]] - X[t.v[0]];
    return 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
}

// Splits triangle slot t across edge (i, j) at n. The slot keeps the half at the
// edge's first vertex; the other half is appended. Orientation is preserved.
// Returns the new triangle's id.
Index splitTriangle(Sheet& sheet, Index t, Index i, Index j, Index n, Index ein, Index enj,
                    Index eon) {
    const Triangle old = sheet.tris[t];
    const int k = sheet.edgeSlot(t, i, j);
    const Index p = old.v[k], q = old.v[(k + 1) % 3], o = old.v[(k + 2) % 3];
    const Index halfP = p == i ? ein : enj;
    const Index halfQ = q == i ? ein : enj;
    const Index eqo = old.e[(k + 1) % 3], eop = old.e[(k + 2) % 3];

    sheet.tris[t] = Triangle{{p, n, o}, {halfP, eon, eop}};
    sheet.tris.push_back(Triangle{{n, q, o}, {halfQ, eqo, eon}});
    const Index t2 = sheet.triangleCount() - 1;
    replaceFace(sheet, eqo, t, t2);
    attachFace(sheet, halfP, t);
    attachFace(sheet, halfQ, t2);
    attachFace(sheet, eon, t);
    attachFace(sheet, eon, t2);
    return t2;
}

// Sweeps of withinReach.
constexpr int kPlacementSweeps = 64;

// A point near `x` within `reach[k]` of each `around[k]`, or, where the balls do not
// meet, one that shares the excess among them (simultaneous projections: each sweep
// moves x by the mean of its moves onto the balls it lies outside).
Vec3 withinReach(Vec3 x, const std::array<Vec3, 4>& around, const std::array<double, 4>& reach) {
    for (int sweep = 0; sweep < kPlacementSweeps; ++sweep) {
        Vec3 move = Vec3::Zero();
        int outside = 0;
        for (std::size_t k = 0; k < around.size(); ++k) {
            const Vec3 d = x - around[k];
            const double len = d.norm();
            if (!(len > reach[k])) continue;
            move += d * (reach[k] / len - 1.0);
            ++outside;
        }
        if (outside == 0) break;
        x += move / outside;
    }
    return x;
}

// What i and j each give the new vertex: a sixth of the rest mass of the two triangles.
double massShare(const Sheet& sheet, Index spring) {
    const auto& faces = sheet.springs.faces[spring];
    return sheet.density *
           (materialArea(sheet, sheet.tris[faces[0]]) + materialArea(sheet, sheet.tris[faces[1]])) /
           6.0;
}

} // namespace

Index breakEdge(Sheet& sheet, Index spring, const std::vector<Vec3>& normals, double psi,
                std::int64_t step, bool keepLengths) {
    auto& V = sheet.verts;
    auto& S = sheet.springs;
    const Index i = S.a[spring], j = S.b[spring];
    const Index t1 = S.faces[spring][0], t2 = S.faces[spring][1];
    const Index r = sheet.oppositeVertex(t1, i, j);
    const Index l = sheet.oppositeVertex(t2, i, j);

    DamageEvent ev;
    sheet.paper.meshChanged();
    ev.kind = EventKind::Break;
    ev.step = step;
    ev.edge = spring;
    ev.oldTris = {sheet.tris[t1], sheet.tris[t2]};

    // Eq. 11, toward the side the edge already bends to: if the edge's midpoint lies
    // above the r-l midpoint along the edge normal, the edge is a ridge and n rises.
    const double len = (V.x[i] - V.x[j]).norm();
    const double l0 = S.rest[spring];
    Vec3 edgeNormal = normals[i] + normals[j];
    edgeNormal = edgeNormal.norm() > 0.0 ? Vec3(edgeNormal.normalized()) : Vec3::UnitY();
    const Vec3 mid = 0.5 * (V.x[i] + V.x[j]);
    const double bulge = (mid - 0.5 * (V.x[r] + V.x[l])).dot(edgeNormal);
    const double side = bulge < 0.0 ? -1.0 : 1.0;
    Vec3 xn = mid + side * breakOffset(len, l0, psi) * edgeNormal;
    // Paper that does not stretch (keepLengths): n goes where none of its four new edges
    // is longer than its rest length, as near Eq. 11's point as that allows. Eq. 11
    // gives the halves their rest length, but the edges across, to r and to l, were
    // left up to 43 % long where a fold had pressed the edge to a fraction of its
    // length (the cell about it sheared), and the next steps pulled them back through
    // the paper around.
    if (keepLengths) {
        const Vec2 Xn = 0.5 * (V.X[i] + V.X[j]);
        xn = withinReach(xn, {V.x[i], V.x[j], V.x[r], V.x[l]},
                         {(V.X[i] - Xn).norm(), (V.X[j] - Xn).norm(), (V.X[r] - Xn).norm(),
                          (V.X[l] - Xn).norm()});
    }

    // Lumped masses follow rest areas: i and j each give up a sixth of the two old
    // triangles' mass, n receives both. Store exactly what was taken so recovery
    // gives it back bit for bit (m - (m - δ) is exact by Sterbenz' lemma).
    const double delta = massShare(sheet, spring);
    const double mi = V.m[i], mj = V.m[j];
    V.m[i] = mi - delta;
    V.m[j] = mj - delta;
    ev.massTaken = {mi - V.m[i], mj - V.m[j]};

    const Index n = sheet.addVertex(xn, 0.5 * (V.v[i] + V.v[j]), ev.massTaken[0] + ev.massTaken[1],
                                    0.5 * (V.X[i] + V.X[j]));
    const std::uint8_t hinged = S.hinged[spring];
    const Index ein =
        sheet.addSpring(i, n, sheet.materialDistance(i, n), SpringKind::Structural, true);
    const Index enj =
        sheet.addSpring(n, j, sheet.materialDistance(n, j), SpringKind::Structural, true);
    const Index ern =
        sheet.addSpring(r, n, sheet.materialDistance(r, n), SpringKind::Structural, false);
    const Index enl =
        sheet.addSpring(n, l, sheet.materialDistance(n, l), SpringKind::Structural, false);
    // The halves lie across the same r-l pair: a hinge already there serves them too.
    S.hinged[ein] = hinged;
    S.hinged[enj] = hinged;

    const Index t3 = splitTriangle(sheet, t1, i, j, n, ein, enj, ern);
    const Index t4 = splitTriangle(sheet, t2, i, j, n, ein, enj, enl);

    // e_ij becomes an unbreakable crease remembering its length now (compressed, for the
    // paper's soft springs; about its rest length for stiff paper read on the arc).
    S.kind[spring] = SpringKind::Crease;
    S.breakable[spring] = 0;
    S.rest[spring] = len;
    S.faces[spring] = {kNone, kNone};

    ev.vertex = n;
    ev.springs = {ein, enj, ern, enl};
    ev.tris = {t1, t2, t3, t4};
    ev.newTris = {sheet.tris[t1], sheet.tris[t2], sheet.tris[t3], sheet.tris[t4]};
    sheet.events.push_back(ev);
    const Index id = static_cast<Index>(sheet.events.size()) - 1;
    S.event[spring] = id;
    return id;
}

bool canRecover(const Sheet& sheet, Index event) {
    if (event < 0 || event >= static_cast<Index>(sheet.events.size())) return false;
    const DamageEvent& ev = sheet.events[event];
    if (!ev.active) return false;
    const auto& S = sheet.springs;
    if (ev.kind == EventKind::Hinge) return true;
    if (S.kind[ev.edge] != SpringKind::Crease || S.event[ev.edge] != event) return false;
    if (!S.breakable[ev.springs[0]] || !S.breakable[ev.springs[1]]) return false;
    for (int k = 0; k < 4; ++k)
        if (!(sheet.tris[ev.tris[k]] == ev.newTris[k])) return false;
    return true;
}

namespace {

void recoverHinge(Sheet& sheet, Index event) {
    DamageEvent& ev = sheet.events[event];
    sheet.springs.hinged[ev.edge] = 0;
    ev.active = false;
    removeSpringAt(sheet, ev.springs[0]);
}

bool isOneOf(Index id, const std::array<Index, 4>& ids) {
    return id == ids[0] || id == ids[1] || id == ids[2] || id == ids[3];
}

} // namespace

bool recoverEvent(Sheet& sheet, Index event) {
    if (!canRecover(sheet, event)) return false;
    sheet.paper.meshChanged();
    if (sheet.events[event].kind == EventKind::Hinge) {
        recoverHinge(sheet, event);
        return true;
    }

    // Hinges that hang on n or on the springs about to go, newest first.
    for (Index h = static_cast<Index>(sheet.events.size()) - 1; h > event; --h) {
        const DamageEvent& hv = sheet.events[h];
        if (!hv.active || hv.kind != EventKind::Hinge) continue;
        const DamageEvent& ev = sheet.events[event];
        const Index hs = hv.springs[0];
        const bool usesN = sheet.springs.a[hs] == ev.vertex || sheet.springs.b[hs] == ev.vertex;
        if (usesN || isOneOf(hv.edge, ev.springs)) recoverHinge(sheet, h);
    }

    // Ids are read from the event after each removal: a removal renames references.
    DamageEvent& ev = sheet.events[event];
    auto& S = sheet.springs;
    const Index i = S.a[ev.edge], j = S.b[ev.edge];

    for (int k = 0; k < 2; ++k) {
        const Index slot = ev.tris[k], moved = ev.tris[k + 2];
        sheet.tris[slot] = ev.oldTris[k];
        for (Index e : ev.oldTris[k].e)
            if (e != ev.edge) replaceFace(sheet, e, moved, slot);
    }
    for (Index s : ev.springs) S.faces[s] = {kNone, kNone};
    removeTriangleAt(sheet, ev.tris[3]);
    removeTriangleAt(sheet, ev.tris[2]);

    S.kind[ev.edge] = SpringKind::Structural;
    S.breakable[ev.edge] = 1;
    S.rest[ev.edge] = sheet.materialDistance(i, j);
    S.faces[ev.edge] = {ev.tris[0], ev.tris[1]};
    S.event[ev.edge] = kNone;

    for (int k = 3; k >= 0; --k) removeSpringAt(sheet, ev.springs[k]);

    sheet.verts.m[i] += ev.massTaken[0];
    sheet.verts.m[j] += ev.massTaken[1];
    ev.active = false;
    removeVertexAt(sheet, ev.vertex);
    return true;
}

namespace {

// A breakable structural edge between two triangles: the mesh has room to split it.
// But an edge a file says is longer than the sheet may ever reach (kDivergenceRadius) is not
// paper: Eq. 11 would lift its new vertex out of the world (the recording fuzzer found a
// rest length of 1.9e185 m).
bool splittable(const Sheet& sheet, Index spring) {
    const auto& S = sheet.springs;
    return S.kind[spring] == SpringKind::Structural && S.breakable[spring] &&
           S.faces[spring][0] != kNone && S.faces[spring][1] != kNone &&
           S.rest[spring] <= kDivergenceRadius;
}

// A sheet from a file may hold masses that do not follow its rest areas; a break that
// would leave i or j without mass is not made.
bool leavesMass(const Sheet& sheet, Index spring) {
    const auto& S = sheet.springs;
    const double share = massShare(sheet, spring);
    return sheet.verts.m[S.a[spring]] > share && sheet.verts.m[S.b[spring]] > share;
}

// Whether the four triangles the split makes are proper in material space, with room to
// spare for rounding. Always so on a sheet this program built; a sheet from a file may
// hold material points a hair apart (the fuzzer found 8e-59 m), and halving a
// triangle that thin rounds it to a line, which no sheet may hold.
bool splitsIntoProperTriangles(const Sheet& sheet, Index spring) {
    const auto& S = sheet.springs;
    const auto& X = sheet.verts.X;
    const Index i = S.a[spring], j = S.b[spring];
    const Vec2 n = 0.5 * (X[i] + X[j]);
    const auto proper = [](const Vec2& p, const Vec2& q, const Vec2& o) {
        const Vec2 a = q - p, b = o - p;
        return std::abs(a.x() * b.y() - a.y() * b.x()) > 1e-9 * a.norm() * b.norm();
    };
    for (const Index face : S.faces[spring]) {
        const Vec2& o = X[sheet.oppositeVertex(face, i, j)];
        if (!proper(X[i], n, o) || !proper(n, X[j], o)) return false;
    }
    return true;
}

} // namespace

bool canBreak(const Sheet& sheet, Index spring) {
    return splittable(sheet, spring) && leavesMass(sheet, spring) &&
           splitsIntoProperTriangles(sheet, spring);
}

namespace {

// A breakable contracted edge between two triangles, not held at both ends and long
// enough to split: one that Eq. 10 applies to. `load` is what the reading found.
bool breakCandidate(const Sheet& sheet, Index spring, double spacing,
                    const ContractionReading& reading, EdgeLoad& load) {
    if (!splittable(sheet, spring)) return false;
    const auto& S = sheet.springs;
    const auto& V = sheet.verts;
    if (V.pinned[S.a[spring]] && V.pinned[S.b[spring]]) return false;
    // The cheap tests first: most edges of a sheet are not contracted at all. An edge
    // squeezed to nothing (pins can hold i on j) is not a candidate: its crease would
    // remember a rest length of zero.
    load = reading.of(sheet, spring);
    if (!(load.chord > 0.0 && load.contraction > 0.0)) return false;
    return leavesMass(sheet, spring) && keepsCreaseSpacing(sheet, spring, spacing) &&
           splitsIntoProperTriangles(sheet, spring);
}

double candidateProbability(const Sheet& sheet, const std::vector<Vec3>& normals, Index spring,
                            const EdgeLoad& load, double phi) {
    const auto& S = sheet.springs;
    const auto& V = sheet.verts;
    const Index i = S.a[spring], j = S.b[spring];
    const Index r = sheet.oppositeVertex(S.faces[spring][0], i, j);
    const Index lv = sheet.oppositeVertex(S.faces[spring][1], i, j);
    return breakProbability(load.length, S.rest[spring], (V.x[r] - V.x[lv]).norm(),
                            normals[i].dot(normals[j]), normals[r].dot(normals[lv]), phi);
}

} // namespace

double springBreakProbability(const Sheet& sheet, const std::vector<Vec3>& normals, Index spring,
                              const SimParams& params) {
    EdgeLoad load;
    return breakCandidate(sheet, spring, params.material.creaseSpacing, readingFor(params, normals),
                          load)
               ? candidateProbability(sheet, normals, spring, load, params.phi)
               : 0.0;
}

bool keepsCreaseSpacing(const Sheet& sheet, Index spring, double spacing) {
    const auto& S = sheet.springs;
    const auto& X = sheet.verts.X;
    const Index i = S.a[spring], j = S.b[spring];
    const Vec2 n = 0.5 * (X[i] + X[j]);
    // The halves i-n and n-j, then the new edges to the two opposite vertices.
    if ((X[i] - n).norm() < spacing) return false;
    for (const Index face : S.faces[spring])
        if ((X[sheet.oppositeVertex(face, i, j)] - n).norm() < spacing) return false;
    return true;
}

void recordCurrentContraction(Sheet& sheet, const SimParams& params) {
    std::vector<Vec3> normals;
    computeVertexNormals(sheet, normals);
    const ContractionReading reading = readingFor(params, normals);
    auto& peak = sheet.springs.peakContraction;
    for (Index s = 0; s < sheet.springs.size(); ++s)
        peak[s] = std::clamp(reading.of(sheet, s).contraction, 0.0, 1.0);
}

void computeBreakProbabilities(const Sheet& sheet, const SimParams& params, BreakScratch& scratch) {
    const Index count = sheet.springs.size();
    scratch.probability.assign(static_cast<std::size_t>(count), 0.0f);
    if (!params.breaking) return;
    computeVertexNormals(sheet, scratch.normals);
    for (Index s = 0; s < count; ++s)
        scratch.probability[s] =
            static_cast<float>(springBreakProbability(sheet, scratch.normals, s, params));
}

int runBreakPass(Sheet& sheet, const SimParams& params, Rng& rng, std::int64_t step,
                 BreakScratch& scratch, const StepWorkers& workers) {
    WorkerPool& pool = workers.poolOrSerial();
    if (workers.stars)
        computeVertexNormals(sheet, scratch.normals, pool, *workers.stars, scratch.triangleNormals);
    else
        computeVertexNormals(sheet, scratch.normals);
    const auto& normals = scratch.normals;
    // Springs appended by a break in this pass are not visited until the next step.
    const Index count = sheet.springs.size();
    scratch.probability.assign(static_cast<std::size_t>(count), 0.0f);
    const ContractionReading reading = readingFor(params, normals);

    // Eq. 10 for every candidate, on the pool's threads: nothing here writes the sheet. The
    // candidates bunch up among the sheet's first springs (the rest are creases and
    // hinges), so the threads take small chunks in turn.
    const int chunks = WorkerPool::kChunksPerThread * pool.threads();
    scratch.candidates.resize(static_cast<std::size_t>(chunks));
    for (auto& chunk : scratch.candidates) chunk.clear();
    pool.forChunks(count, chunks, [&](int chunk, Index begin, Index end) {
        auto& found = scratch.candidates[static_cast<std::size_t>(chunk)];
        EdgeLoad load;
        for (Index s = begin; s < end; ++s) {
            if (!breakCandidate(sheet, s, params.material.creaseSpacing, reading, load)) continue;
            found.push_back(
                {s, candidateProbability(sheet, normals, s, load, params.phi), load.contraction});
        }
    });

    // Then the draws and the breaks, in index order. A break moves no vertex and changes
    // only the triangles it splits (marked touched, their edges wait for the next step)
    // and the masses of its ends, so what was read above still holds for every other
    // candidate, except that its ends may now be too light to give mass again.
    scratch.touched.assign(sheet.tris.size(), 0);
    scratch.massGiven.assign(static_cast<std::size_t>(sheet.verts.size()), 0);
    auto& S = sheet.springs;
    int breaks = 0;
    for (const auto& chunk : scratch.candidates) {
        for (const BreakScratch::Candidate& c : chunk) {
            const Index s = c.spring;
            // A triangle split in this pass may have the new vertex opposite, which has no
            // normal yet: its edges wait for the next step (and show 0 until then).
            const auto& faces = S.faces[s];
            if (scratch.touched[faces[0]] || scratch.touched[faces[1]]) continue;
            if ((scratch.massGiven[S.a[s]] || scratch.massGiven[S.b[s]]) && !leavesMass(sheet, s))
                continue;
            scratch.probability[s] = static_cast<float>(c.probability);
            double& peak = S.peakContraction[s];
            const double growth = c.contraction - peak;
            if (!(growth > 0.0)) continue;
            peak = c.contraction;
            const double p =
                breakProbabilityForGrowth(c.probability, growth, params.breakReferenceContraction);
            if (!(rng.uniform() < p)) continue;
            scratch.massGiven[S.a[s]] = scratch.massGiven[S.b[s]] = 1;
            const Index ev =
                breakEdge(sheet, s, normals, params.psi, step, keepsEdgeLengths(params.integrator));
            scratch.probability[s] = 0.0f; // a crease now: it cannot break again
            for (Index t : sheet.events[ev].tris) {
                if (t >= static_cast<Index>(scratch.touched.size()))
                    scratch.touched.resize(t + 1, 0);
                scratch.touched[t] = 1;
            }
            ++breaks;
        }
    }
    return breaks;
}

} // namespace pf
