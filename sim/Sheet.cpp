#include "Sheet.h"

namespace pf {

Index Sheet::addSpring(Index a, Index b, double rest, SpringKind kind, bool breakable) {
    auto& s = springs;
    s.a.push_back(a);
    s.b.push_back(b);
    s.rest.push_back(rest);
    s.kind.push_back(kind);
    s.breakable.push_back(breakable ? 1 : 0);
    s.hinged.push_back(0);
    s.faces.push_back({kNone, kNone});
    s.event.push_back(kNone);
    s.peakContraction.push_back(0.0);
    return s.size() - 1;
}

Index Sheet::addVertex(const Vec3& x, const Vec3& v, double m, const Vec2& X) {
    verts.x.push_back(x);
    verts.v.push_back(v);
    verts.m.push_back(m);
    verts.X.push_back(X);
    verts.pinned.push_back(0);
    return verts.size() - 1;
}

Index Sheet::oppositeVertex(Index t, Index a, Index b) const {
    for (Index w : tris[t].v)
        if (w != a && w != b) return w;
    return kNone;
}

int Sheet::edgeSlot(Index t, Index a, Index b) const {
    const auto& v = tris[t].v;
    for (int k = 0; k < 3; ++k) {
        const Index p = v[k], q = v[(k + 1) % 3];
        if ((p == a && q == b) || (p == b && q == a)) return k;
    }
    return -1;
}

void Sheet::reserveFor(Index extraVertices) {
    const auto nv = static_cast<std::size_t>(verts.size() + extraVertices);
    // A break adds one vertex, four springs and two triangles; a hinge one spring.
    const auto ns = static_cast<std::size_t>(springs.size() + 6 * extraVertices);
    const auto nt = tris.size() + 2 * static_cast<std::size_t>(extraVertices);
    verts.x.reserve(nv);
    verts.v.reserve(nv);
    verts.m.reserve(nv);
    verts.X.reserve(nv);
    verts.pinned.reserve(nv);
    auto& s = springs;
    s.a.reserve(ns);
    s.b.reserve(ns);
    s.rest.reserve(ns);
    s.kind.reserve(ns);
    s.breakable.reserve(ns);
    s.hinged.reserve(ns);
    s.faces.reserve(ns);
    s.event.reserve(ns);
    s.peakContraction.reserve(ns);
    tris.reserve(nt);
}

} // namespace pf
