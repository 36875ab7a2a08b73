#include "SheetValidation.h"

#include <cmath>
#include <string>
#include <vector>

namespace pf {

namespace {

std::string str(long v) {
    return std::to_string(v);
}

bool finite(const Vec3& p) {
    return p.allFinite();
}

// A sheet is a few metres across and stays near its desk; a point farther out than this
// is a corrupt file, and a renderer working in single precision could not frame it.
constexpr double kMaxCoordinate = 1e4;

bool withinReach(const Vec3& p) {
    return p.cwiseAbs().maxCoeff() <= kMaxCoordinate;
}

} // namespace

std::string validateSheet(const Sheet& sheet) {
    const auto& V = sheet.verts;
    const auto& S = sheet.springs;
    const std::size_t nv = V.x.size();
    if (V.v.size() != nv || V.m.size() != nv || V.X.size() != nv || V.pinned.size() != nv)
        return "vertex arrays differ in length";
    const std::size_t ns = S.a.size();
    if (S.b.size() != ns || S.rest.size() != ns || S.kind.size() != ns ||
        S.breakable.size() != ns || S.hinged.size() != ns || S.faces.size() != ns ||
        S.event.size() != ns || S.peakContraction.size() != ns)
        return "spring arrays differ in length";
    if (!(std::isfinite(sheet.density) && sheet.density > 0.0)) return "density is not positive";

    const Index nvi = static_cast<Index>(nv);
    const Index nt = sheet.triangleCount();
    const Index ne = static_cast<Index>(sheet.events.size());
    auto inV = [&](Index i) { return i >= 0 && i < nvi; };
    auto inS = [&](Index s) { return s >= 0 && s < static_cast<Index>(ns); };
    auto inT = [&](Index t) { return t >= 0 && t < nt; };

    for (Index i = 0; i < nvi; ++i) {
        if (!finite(V.x[i]) || !finite(V.v[i]) || !V.X[i].allFinite())
            return "vertex " + str(i) + " has a non-finite coordinate";
        if (!withinReach(V.x[i]) || V.X[i].cwiseAbs().maxCoeff() > kMaxCoordinate)
            return "vertex " + str(i) + " lies more than 10 km from the origin";
        if (!(std::isfinite(V.m[i]) && V.m[i] > 0.0))
            return "vertex " + str(i) + " has a non-positive mass";
        if (V.pinned[i] > 1) return "vertex " + str(i) + " has an invalid pinned flag";
    }

    for (Index s = 0; s < static_cast<Index>(ns); ++s) {
        const std::string at = "spring " + str(s);
        if (!inV(S.a[s]) || !inV(S.b[s])) return at + " has a vertex out of range";
        if (S.a[s] == S.b[s]) return at + " joins a vertex to itself";
        if (static_cast<int>(S.kind[s]) >= kSpringKindCount) return at + " has an unknown kind";
        if (!(std::isfinite(S.rest[s]) && S.rest[s] > 0.0))
            return at + " has a non-positive rest length";
        if (S.breakable[s] > 1 || S.hinged[s] > 1) return at + " has an invalid flag";
        if (!(S.peakContraction[s] >= 0.0 && S.peakContraction[s] <= 1.0))
            return at + " has a peak contraction outside [0, 1]";
        const bool structural = S.kind[s] == SpringKind::Structural;
        if (S.breakable[s] && !structural) return at + " is breakable but not structural";
        for (Index f : S.faces[s]) {
            if (f == kNone) continue;
            if (!structural) return at + " has faces but is not a triangle edge";
            if (!inT(f)) return at + " has a face out of range";
            if (sheet.edgeSlot(f, S.a[s], S.b[s]) < 0 ||
                sheet.tris[f].e[sheet.edgeSlot(f, S.a[s], S.b[s])] != s)
                return at + " lists triangle " + str(f) + " which does not contain it";
        }
        if (structural && S.faces[s][0] == kNone && S.faces[s][1] == kNone)
            return at + " is structural but belongs to no triangle";
        if (S.faces[s][0] != kNone && S.faces[s][0] == S.faces[s][1])
            return at + " lists the same triangle twice";
        if (S.event[s] != kNone && (S.event[s] < 0 || S.event[s] >= ne))
            return at + " points at a log event out of range";
        const bool needsEvent = S.kind[s] == SpringKind::Crease || S.kind[s] == SpringKind::Hinge;
        if (needsEvent != (S.event[s] != kNone))
            return at + (needsEvent ? " has no log event" : " has a log event but no need of one");
    }

    std::vector<std::uint8_t> used(nv, 0);
    for (Index t = 0; t < nt; ++t) {
        const Triangle& tri = sheet.tris[t];
        const std::string at = "triangle " + str(t);
        for (int k = 0; k < 3; ++k) {
            if (!inV(tri.v[k])) return at + " has a vertex out of range";
            if (!inS(tri.e[k])) return at + " has an edge out of range";
        }
        if (tri.v[0] == tri.v[1] || tri.v[1] == tri.v[2] || tri.v[0] == tri.v[2])
            return at + " repeats a vertex";
        for (int k = 0; k < 3; ++k) {
            const Index e = tri.e[k], p = tri.v[k], q = tri.v[(k + 1) % 3];
            if (S.kind[e] != SpringKind::Structural) return at + " has a non-structural edge";
            if (!((S.a[e] == p && S.b[e] == q) || (S.a[e] == q && S.b[e] == p)))
                return at + " edge " + str(k) + " does not join its vertices";
            if (S.faces[e][0] != t && S.faces[e][1] != t)
                return at + " is not listed as a face of its edge " + str(e);
            used[p] = 1;
        }
        const Vec2 a = V.X[tri.v[1]] - V.X[tri.v[0]];
        const Vec2 b = V.X[tri.v[2]] - V.X[tri.v[0]];
        if (!(std::abs(a.x() * b.y() - a.y() * b.x()) > 0.0))
            return at + " is degenerate in material space";
    }
    for (Index i = 0; i < nvi; ++i)
        if (!used[i]) return "vertex " + str(i) + " belongs to no triangle";

    for (Index e = 0; e < ne; ++e) {
        const DamageEvent& ev = sheet.events[e];
        if (!ev.active) continue;
        const std::string at = "log event " + str(e);
        if (static_cast<int>(ev.kind) > 1) return at + " has an unknown kind";
        if (!inS(ev.edge)) return at + " has an edge out of range";
        if (ev.kind == EventKind::Hinge) {
            if (!inS(ev.springs[0]) || S.kind[ev.springs[0]] != SpringKind::Hinge ||
                S.event[ev.springs[0]] != e)
                return at + " does not point at its hinge spring";
            continue;
        }
        if (S.kind[ev.edge] != SpringKind::Crease || S.event[ev.edge] != e)
            return at + " does not point at its crease spring";
        if (!inV(ev.vertex)) return at + " has a vertex out of range";
        for (Index s : ev.springs)
            if (!inS(s)) return at + " has a spring out of range";
        for (Index t : ev.tris)
            if (!inT(t)) return at + " has a triangle out of range";
        for (const Triangle& t : ev.oldTris)
            for (int k = 0; k < 3; ++k)
                if (!inV(t.v[k]) || !inS(t.e[k])) return at + " has a stored triangle out of range";
        // What recovery will rely on: the springs join i-n, n-j, r-n, n-l, and each
        // stored triangle holds the crease's two ends and the edge itself.
        const Index i = S.a[ev.edge], j = S.b[ev.edge], n = ev.vertex;
        auto joins = [&](Index s, Index p, Index q) {
            return (S.a[s] == p && S.b[s] == q) || (S.a[s] == q && S.b[s] == p);
        };
        if (n == i || n == j || !joins(ev.springs[0], i, n) || !joins(ev.springs[1], n, j) ||
            !(S.a[ev.springs[2]] == n || S.b[ev.springs[2]] == n) ||
            !(S.a[ev.springs[3]] == n || S.b[ev.springs[3]] == n))
            return at + " has springs that do not meet at its vertex";
        for (const Triangle& t : ev.oldTris) {
            int ends = 0, hasEdge = 0;
            for (int k = 0; k < 3; ++k) {
                ends += t.v[k] == i || t.v[k] == j;
                hasEdge += t.e[k] == ev.edge;
            }
            if (ends != 2 || hasEdge != 1) return at + " has a stored triangle without its edge";
        }
        if (!(std::isfinite(ev.massTaken[0]) && std::isfinite(ev.massTaken[1])))
            return at + " has a non-finite mass";
    }
    for (const PaperState::PlasticBend& p : sheet.paper.plastic) {
        int used = 0;
        for (std::size_t slot = 0; slot < p.vertices.size(); ++slot) {
            const Index v = p.vertices[slot];
            if (v == kNone) continue;
            if (v < 0 || v >= nvi) return "a plastic bend names a vertex that does not exist";
            if (used != static_cast<int>(slot))
                return "a plastic bend has a gap among its vertices";
            ++used;
        }
        for (int a = 0; a < used; ++a)
            for (int b = a + 1; b < used; ++b)
                if (p.vertices[a] == p.vertices[b]) return "a plastic bend repeats a vertex";
        if (used < 3 || !p.rest.allFinite()) return "a plastic bend is malformed";
    }
    std::vector<std::uint8_t> gripped(static_cast<std::size_t>(nt), 0);
    for (const PaperState::ToolGrip& g : sheet.paper.grips) {
        if (g.triangle < 0 || g.triangle >= nt || gripped[g.triangle]++)
            return "a tool grip names a missing or repeated triangle";
        const Vec3& b = g.barycentric;
        if (!b.allFinite() || b.minCoeff() < -1e-9 || std::abs(b.sum() - 1.0) > 1e-6 ||
            !g.offset.allFinite() || g.offset.norm() > 100.0)
            return "a tool grip is malformed";
    }
    if (sheet.paper.quietSteps < 0) return "negative quiet steps";
    for (const PaperState::StillWatch* watch : {&sheet.paper.still, &sheet.paper.slowStill}) {
        if (watch->steps < 0) return "negative still steps";
        for (const auto* positions : {&watch->from, &watch->mean}) {
            if (!positions->empty() && positions->size() != static_cast<std::size_t>(nv))
                return "the still positions do not match the vertices";
            for (const Vec3& p : *positions)
                if (!finite(p)) return "a still position is not finite";
        }
    }
    const double slide = sheet.paper.deskSlide;
    if (!(slide == kSlideUnknown || (std::isfinite(slide) && slide >= 0.0)))
        return "the sheet's slide across the desk is malformed";
    return {};
}

long eulerCharacteristic(const Sheet& sheet) {
    long edges = 0;
    for (SpringKind k : sheet.springs.kind)
        if (k == SpringKind::Structural) ++edges;
    return static_cast<long>(sheet.verts.size()) - edges + static_cast<long>(sheet.tris.size());
}

} // namespace pf
