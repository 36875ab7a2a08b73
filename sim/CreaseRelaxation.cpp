#include "CreaseRelaxation.h"

namespace pf {

namespace {

// Sweeps, forward and back, and the stretch below which the paper round a new crease
// counts as settled (the fast projection's target is 0.3 %). Each sweep moves a pull one
// edge, and at 32 a break in a gathered sheet kept 1.4-1.7 % (from 5.2 %); it stops
// as soon as the paper has settled.
constexpr int kRelaxationSweeps = 512;
constexpr double kSettledStretch = 1e-4;
// The new vertices move, and the paper this many structural edges round them. With one
// ring, a break in a gathered sheet left 8.5 % of its 31 % after all 512 sweeps: the
// ring's far ends held the stretch in place. With two, the first cycle of
// crumple-cycles keeps every step under 0.6 % over three seeds and three projection
// compliances (docs/speed.md).
constexpr int kMovableRings = 2;

} // namespace

std::vector<Index> relaxAroundNewVertices(Sheet& sheet, Index firstNew) {
    auto& V = sheet.verts;
    const auto& S = sheet.springs;
    const Index nv = V.size();
    std::vector<Index> moved;
    if (firstNew >= nv) return moved;
    // What may move: the new vertices and the rings round them, but pins.
    std::vector<std::uint8_t> movable(static_cast<std::size_t>(nv), 0);
    for (Index i = firstNew; i < nv; ++i) movable[static_cast<std::size_t>(i)] = 1;
    for (int ring = 0; ring < kMovableRings; ++ring) {
        const std::vector<std::uint8_t> inner = movable;
        for (Index s = 0; s < S.size(); ++s) {
            if (S.kind[s] != SpringKind::Structural) continue;
            if (inner[static_cast<std::size_t>(S.a[s])])
                movable[static_cast<std::size_t>(S.b[s])] = 1;
            if (inner[static_cast<std::size_t>(S.b[s])])
                movable[static_cast<std::size_t>(S.a[s])] = 1;
        }
    }
    for (Index i = 0; i < nv; ++i) {
        auto& m = movable[static_cast<std::size_t>(i)];
        if (m && V.pinned[i]) m = 0;
        if (m) moved.push_back(i);
    }
    // The edges that hold them: every structural edge with a movable end.
    std::vector<Index> edges;
    for (Index s = 0; s < S.size(); ++s)
        if (S.kind[s] == SpringKind::Structural && (movable[static_cast<std::size_t>(S.a[s])] ||
                                                    movable[static_cast<std::size_t>(S.b[s])]))
            edges.push_back(s);
    const auto weight = [&](Index i) {
        return movable[static_cast<std::size_t>(i)] ? 1.0 / V.m[i] : 0.0;
    };
    for (int sweep = 0; sweep < kRelaxationSweeps; ++sweep) {
        double worst = 0.0;
        const auto relax = [&](Index s) {
            const Index a = S.a[s], b = S.b[s];
            const Vec3 d = V.x[a] - V.x[b];
            const double len = d.norm();
            if (!(len > S.rest[s])) return;
            worst = std::max(worst, len / S.rest[s] - 1.0);
            const double wa = weight(a), wb = weight(b);
            if (wa + wb == 0.0) return;
            const Vec3 move = d * ((len - S.rest[s]) / (len * (wa + wb)));
            V.x[a] -= wa * move;
            V.x[b] += wb * move;
        };
        if (sweep % 2 == 0)
            for (Index s : edges) relax(s);
        else
            for (auto it = edges.rbegin(); it != edges.rend(); ++it) relax(*it);
        if (worst <= kSettledStretch) break;
    }
    return moved;
}

} // namespace pf
