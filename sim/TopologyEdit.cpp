#include "TopologyEdit.h"

#include <algorithm>

namespace pf {

namespace {

template <class Vec> void moveLastInto(Vec& v, Index slot) {
    v[static_cast<std::size_t>(slot)] = v.back();
    v.pop_back();
}

void rename(Index& id, Index from, Index to) {
    if (id == from) id = to;
}

void renameSpringInTriangle(Triangle& t, Index from, Index to) {
    for (Index& e : t.e) rename(e, from, to);
}

void renameVertexInTriangle(Triangle& t, Index from, Index to) {
    for (Index& w : t.v) rename(w, from, to);
}

} // namespace

void replaceFace(Sheet& sheet, Index spring, Index from, Index to) {
    for (Index& f : sheet.springs.faces[spring]) rename(f, from, to);
}

void attachFace(Sheet& sheet, Index spring, Index t) {
    auto& f = sheet.springs.faces[spring];
    if (f[0] == kNone)
        f[0] = t;
    else
        f[1] = t;
}

void removeSpringAt(Sheet& sheet, Index s) {
    auto& S = sheet.springs;
    const Index last = S.size() - 1;
    if (s != last) {
        for (Index f : S.faces[last])
            if (f != kNone) renameSpringInTriangle(sheet.tris[f], last, s);
        for (auto& ev : sheet.events) {
            if (!ev.active) continue;
            rename(ev.edge, last, s);
            for (Index& id : ev.springs) rename(id, last, s);
            for (auto& t : ev.oldTris) renameSpringInTriangle(t, last, s);
            for (auto& t : ev.newTris) renameSpringInTriangle(t, last, s);
        }
    }
    moveLastInto(S.a, s);
    moveLastInto(S.b, s);
    moveLastInto(S.rest, s);
    moveLastInto(S.kind, s);
    moveLastInto(S.breakable, s);
    moveLastInto(S.hinged, s);
    moveLastInto(S.faces, s);
    moveLastInto(S.event, s);
    moveLastInto(S.peakContraction, s);
}

void removeTriangleAt(Sheet& sheet, Index t) {
    const Index last = sheet.triangleCount() - 1;
    if (t != last) {
        for (Index e : sheet.tris[last].e) replaceFace(sheet, e, last, t);
        for (auto& ev : sheet.events)
            if (ev.active)
                for (Index& id : ev.tris) rename(id, last, t);
    }
    moveLastInto(sheet.tris, t);
}

void removeVertexAt(Sheet& sheet, Index v) {
    auto& V = sheet.verts;
    const Index last = V.size() - 1;
    // Plastic folds around the removed vertex go with it; the others follow the rename.
    auto& plastic = sheet.paper.plastic;
    std::erase_if(plastic, [v](const PaperState::PlasticBend& p) {
        return std::find(p.vertices.begin(), p.vertices.end(), v) != p.vertices.end();
    });
    for (PaperState::PlasticBend& p : plastic)
        for (Index& id : p.vertices) rename(id, last, v);
    if (v != last) {
        auto& S = sheet.springs;
        for (Index s = 0; s < S.size(); ++s) {
            rename(S.a[s], last, v);
            rename(S.b[s], last, v);
        }
        for (auto& t : sheet.tris) renameVertexInTriangle(t, last, v);
        for (auto& ev : sheet.events) {
            if (!ev.active) continue;
            rename(ev.vertex, last, v);
            for (auto& t : ev.oldTris) renameVertexInTriangle(t, last, v);
            for (auto& t : ev.newTris) renameVertexInTriangle(t, last, v);
        }
    }
    moveLastInto(V.x, v);
    moveLastInto(V.v, v);
    moveLastInto(V.m, v);
    moveLastInto(V.X, v);
    moveLastInto(V.pinned, v);
}

} // namespace pf
