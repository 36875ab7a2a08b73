#include "CreaseNetwork.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace pf {

std::vector<CreaseEdge> creaseEdges(const Sheet& s) {
    std::vector<CreaseEdge> edges;
    for (const DamageEvent& ev : s.events) {
        if (!ev.active || ev.kind != EventKind::Break) continue;
        for (const Index spring : {ev.springs[2], ev.springs[3]}) { // e_rn, e_nl
            const Index a = s.springs.a[spring], b = s.springs.b[spring];
            edges.push_back({a, b, (s.verts.X[a] - s.verts.X[b]).norm()});
        }
    }
    return edges;
}

CreaseNetwork measureCreases(const Sheet& sheet) {
    const std::vector<CreaseEdge> edges = creaseEdges(sheet);
    CreaseNetwork net;
    std::vector<std::vector<std::size_t>> at(static_cast<std::size_t>(sheet.verts.size()));
    for (std::size_t e = 0; e < edges.size(); ++e) {
        net.totalLength += edges[e].length;
        at[edges[e].a].push_back(e);
        at[edges[e].b].push_back(e);
    }
    const auto other = [&](std::size_t e, Index v) {
        return edges[e].a == v ? edges[e].b : edges[e].a;
    };
    // The edge the run entering `v` along `e` goes on along, or edges.size() where it ends.
    const auto next = [&](std::size_t e, Index v) {
        const auto& here = at[v];
        if (here.size() != 2) return edges.size();
        const std::size_t f = here[0] == e ? here[1] : here[0];
        const Vec2 in = sheet.verts.X[v] - sheet.verts.X[other(e, v)];
        const Vec2 out = sheet.verts.X[other(f, v)] - sheet.verts.X[v];
        const double turn = std::atan2(std::abs(in.x() * out.y() - in.y() * out.x()), in.dot(out));
        return turn < kCreaseRunMaxTurn ? f : edges.size();
    };
    std::vector<char> taken(edges.size(), 0);
    for (std::size_t start = 0; start < edges.size(); ++start) {
        if (taken[start]) continue;
        taken[start] = 1;
        double run = edges[start].length;
        // Both ways from the first edge; a closed loop stops where it began.
        for (Index v : {edges[start].a, edges[start].b}) {
            std::size_t e = start;
            for (std::size_t f = next(e, v); f < edges.size() && !taken[f]; f = next(e, v)) {
                taken[f] = 1;
                run += edges[f].length;
                v = other(f, v);
                e = f;
            }
        }
        net.segments.push_back(run);
    }
    std::sort(net.segments.begin(), net.segments.end(), std::greater<>());
    return net;
}

} // namespace pf
