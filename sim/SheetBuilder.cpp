#include "SheetBuilder.h"

#include <cmath>
#include <map>
#include <utility>

namespace pf {

SheetSpec a4Spec(int resolution) {
    const SheetSpec a4;
    return sizedSpec(resolution, a4.width, a4.length);
}

SheetSpec sizedSpec(int resolution, double width, double length) {
    SheetSpec spec;
    spec.width = width;
    spec.length = length;
    spec.columns = resolution;
    spec.rows = static_cast<int>(std::lround((resolution - 1) * spec.length / spec.width)) + 1;
    return spec;
}

Sheet buildRectangleSheet(const SheetSpec& spec) {
    Sheet sheet;
    sheet.density = spec.density;
    const int nc = spec.columns, nr = spec.rows;
    for (int r = 0; r < nr; ++r)
        for (int c = 0; c < nc; ++c) {
            const Vec2 X(-0.5 * spec.width + spec.width * c / (nc - 1),
                         -0.5 * spec.length + spec.length * r / (nr - 1));
            sheet.addVertex(Vec3(X.x(), spec.height, X.y()), Vec3::Zero(), 0.0, X);
        }

    std::map<std::pair<Index, Index>, Index> edgeOf;
    auto edge = [&](Index p, Index q) {
        const auto key = std::minmax(p, q);
        auto it = edgeOf.find(key);
        if (it != edgeOf.end()) return it->second;
        const Index s =
            sheet.addSpring(p, q, sheet.materialDistance(p, q), SpringKind::Structural, true);
        edgeOf.emplace(key, s);
        return s;
    };
    // Counter-clockwise seen from +y, so normals of the flat sheet point up.
    auto addTriangle = [&](Index p, Index q, Index o) {
        Triangle t{{p, q, o}, {edge(p, q), edge(q, o), edge(o, p)}};
        sheet.tris.push_back(t);
        const Index id = sheet.triangleCount() - 1;
        for (Index e : t.e) {
            auto& f = sheet.springs.faces[e];
            (f[0] == kNone ? f[0] : f[1]) = id;
        }
    };
    for (int r = 0; r + 1 < nr; ++r)
        for (int c = 0; c + 1 < nc; ++c) {
            const Index v00 = r * nc + c, v10 = v00 + 1, v01 = v00 + nc, v11 = v01 + 1;
            if ((r + c) % 2 == 0) {
                addTriangle(v00, v01, v11);
                addTriangle(v00, v11, v10);
            } else {
                addTriangle(v00, v01, v10);
                addTriangle(v10, v01, v11);
            }
        }

    // Lumped masses: a third of each triangle's rest mass to each corner.
    auto& m = sheet.verts.m;
    for (const Triangle& t : sheet.tris) {
        const Vec2 a = sheet.verts.X[t.v[1]] - sheet.verts.X[t.v[0]];
        const Vec2 b = sheet.verts.X[t.v[2]] - sheet.verts.X[t.v[0]];
        const double share = spec.density * 0.5 * std::abs(a.x() * b.y() - a.y() * b.x()) / 3.0;
        for (Index w : t.v) m[w] += share;
    }

    const Index structural = sheet.springs.size();
    for (Index s = 0; s < structural; ++s) {
        const auto f = sheet.springs.faces[s];
        if (f[0] == kNone || f[1] == kNone) continue;
        const Index r = sheet.oppositeVertex(f[0], sheet.springs.a[s], sheet.springs.b[s]);
        const Index l = sheet.oppositeVertex(f[1], sheet.springs.a[s], sheet.springs.b[s]);
        sheet.addSpring(r, l, sheet.materialDistance(r, l), SpringKind::Bending, false);
    }
    return sheet;
}

} // namespace pf
