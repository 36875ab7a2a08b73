#include "XpbdIntegrator.h"

#include "AirDrag.h"
#include "DeskHold.h"
#include "PinPivot.h"
#include "TriangleGeometry.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>

namespace pf {

namespace {

double cross2(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

double restArea(const Sheet& sheet, const Triangle& t) {
    const auto& X = sheet.verts.X;
    return 0.5 * std::abs(cross2(X[t.v[1]] - X[t.v[0]], X[t.v[2]] - X[t.v[0]]));
}

// Each triangle's share of E·t on its three edges. For the right triangles of the
// initial grid the shares are exact for ν = 1/3 (a linear-elastic triangle of legs a and
// b is matched by three springs); triangles a break made take the square cell's value.
void addTriangleStiffness(const Sheet& sheet, const Triangle& t, double et,
                          std::vector<double>& k) {
    const auto& X = sheet.verts.X;
    for (int c = 0; c < 3; ++c) {
        const Index vc = t.v[c], va = t.v[(c + 1) % 3], vb = t.v[(c + 2) % 3];
        const Vec2 ea = X[va] - X[vc], eb = X[vb] - X[vc];
        const double la = ea.norm(), lb = eb.norm();
        if (la <= 0.0 || lb <= 0.0 || std::abs(ea.dot(eb)) > 1e-9 * la * lb) continue;
        // Right angle at vc: edge c joins vc-va (leg a), edge c+2 joins vb-vc (leg b),
        // edge c+1 is the hypotenuse.
        const double floor = 0.05 * et;
        k[t.e[c]] += std::max(floor, et * (9.0 * lb / la - 3.0 * la / lb) / 16.0);
        k[t.e[(c + 2) % 3]] += std::max(floor, et * (9.0 * la / lb - 3.0 * lb / la) / 16.0);
        k[t.e[(c + 1) % 3]] += 3.0 * et * (la * la + lb * lb) / (16.0 * la * lb);
        return;
    }
    for (Index e : t.e) k[e] += 0.375 * et;
}

// Euler buckling of the strip spring s stands for (width (A1 + A2) / l0, pinned ends):
// more push than this and real paper buckles out of plane at a scale finer than the
// mesh, which is what a break stands for.
double bucklingLoad(const Sheet& sheet, Index s, const Material& m) {
    const auto& S = sheet.springs;
    double area = 0.0;
    for (Index t : S.faces[s])
        if (t != kNone) area += restArea(sheet, sheet.tris[t]);
    const double l0 = S.rest[s];
    return std::numbers::pi * std::numbers::pi * m.bendingStiffness * area / (l0 * l0 * l0);
}

} // namespace

std::vector<double> XpbdIntegrator::stretchStiffness(const Sheet& sheet, const Material& m) {
    const auto& S = sheet.springs;
    std::vector<double> k(static_cast<std::size_t>(S.size()), 0.0);
    for (const Triangle& t : sheet.tris) addTriangleStiffness(sheet, t, m.stretchStiffness, k);
    // A crease remembers the compressed length it broke at, as stiffly as the paper.
    for (Index s = 0; s < S.size(); ++s)
        if (S.kind[s] == SpringKind::Crease) k[s] = 0.75 * m.stretchStiffness;
    return k;
}

namespace {

// The rows and columns of the grid buildRectangleSheet made, if the sheet starts with
// one: vertex r·columns + c at X0 + (c·hx, r·hz).
struct Grid {
    int columns = 0, rows = 0;
    double hx = 0.0, hz = 0.0;
};

Grid findGrid(const Sheet& sheet) {
    const auto& X = sheet.verts.X;
    const Index nv = sheet.verts.size();
    Grid g;
    if (nv < 4) return {};
    while (g.columns < nv && X[g.columns].y() == X[0].y()) ++g.columns;
    if (g.columns < 2 || g.columns >= nv) return {};
    g.hx = X[1].x() - X[0].x();
    g.hz = X[g.columns].y() - X[0].y();
    if (!(g.hx > 0.0) || !(g.hz > 0.0)) return {};
    const auto at = [&](Index i, int r, int c) {
        return std::abs(X[i].x() - (X[0].x() + c * g.hx)) < 1e-9 &&
               std::abs(X[i].y() - (X[0].y() + r * g.hz)) < 1e-9;
    };
    while ((g.rows + 1) * g.columns <= nv && at(g.rows * g.columns, g.rows, 0)) ++g.rows;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.columns; ++c)
            if (!at(r * g.columns + c, r, c)) return {};
    return g.rows >= 2 ? g : Grid{};
}

// Edge stencil (Bergou et al. 2006) across interior edge s: i, j, r, l, scaled so that
// folding one side by a small angle θ gives |Σ k x| = len θ; energy ½ D len² θ² / A.
bool edgeStencil(const Sheet& sheet, Index s, XpbdIntegrator::Stencil& st, double& area) {
    const auto& S = sheet.springs;
    const auto& X = sheet.verts.X;
    const auto f = S.faces[s];
    if (f[0] == kNone || f[1] == kNone) return false;
    st.count = 4;
    st.v = {S.a[s], S.b[s], sheet.oppositeVertex(f[0], S.a[s], S.b[s]),
            sheet.oppositeVertex(f[1], S.a[s], S.b[s]), kNone};
    for (int c = 0; c < 4; ++c) {
        Vec2 p[3];
        for (int q = 0, n = 0; q < 4; ++q)
            if (q != c) p[n++] = X[st.v[q]];
        st.k[c] = (c % 2 == 0 ? 1.0 : -1.0) * cross2(p[1] - p[0], p[2] - p[0]);
    }
    const Vec2 edge = X[st.v[1]] - X[st.v[0]];
    const double len = edge.norm();
    const double dl = std::abs(cross2(edge, X[st.v[3]] - X[st.v[0]])) / len;
    if (!(len > 0.0) || !(std::abs(st.k[3]) * dl > 0.0)) return false;
    const double scale = len / (std::abs(st.k[3]) * dl);
    for (int q = 0; q < 4; ++q) st.k[q] *= scale;
    area = restArea(sheet, sheet.tris[f[0]]) + restArea(sheet, sheet.tris[f[1]]);
    return true;
}

} // namespace

std::vector<XpbdIntegrator::Stencil> XpbdIntegrator::bendingStencils(const Sheet& sheet,
                                                                     const Material& m) {
    const auto& S = sheet.springs;
    const Index nv = sheet.verts.size();
    const double d = m.bendingStiffness;
    // Vertices a break inserted, and the ends of every broken edge: bending around
    // them is the crease's, kCreaseBendingShare of the paper's.
    std::vector<std::uint8_t> creased(static_cast<std::size_t>(nv), 0);
    for (const DamageEvent& ev : sheet.events) {
        if (!ev.active || ev.kind != EventKind::Break) continue;
        if (ev.vertex != kNone) creased[ev.vertex] = 1;
        if (ev.edge != kNone) creased[S.a[ev.edge]] = creased[S.b[ev.edge]] = 1;
    }
    std::vector<Stencil> out;
    const auto add = [&](Stencil st, double stiffness) {
        // Σ k x for a cylindrical bend of unit curvature across the direction e, the
        // way paper bends (it is developable): ½ (e·X)² gives eᵀ A e with A the 2×2 form
        // below; the stencil's unit is its largest reading over all directions. Read
        // for a bowl instead (½|X|², 2 for the sum of the two second differences), the
        // plate's sum stencils yielded only at twice the curvature of the others, stayed
        // elastic across a fold and pulled it back toward flat (docs/model.md).
        double xx = 0.0, yy = 0.0, xy = 0.0;
        for (int q = 0; q < st.count; ++q) {
            const Vec2 d = sheet.verts.X[st.v[q]] - sheet.verts.X[st.v[0]];
            xx += st.k[q] * 0.5 * d.x() * d.x();
            yy += st.k[q] * 0.5 * d.y() * d.y();
            xy += st.k[q] * 0.5 * d.x() * d.y();
        }
        const double mean = 0.5 * (xx + yy), spread = std::hypot(0.5 * (xx - yy), xy);
        st.unit = std::max(std::abs(mean + spread), std::abs(mean - spread));
        for (int q = 0; q < st.count; ++q)
            for (int o = q + 1; o < st.count; ++o)
                st.span = std::max(st.span,
                                   0.5 * (sheet.verts.X[st.v[q]] - sheet.verts.X[st.v[o]]).norm());
        bool crease = false;
        for (int q = 0; q < st.count; ++q) crease = crease || creased[st.v[q]];
        if (crease) stiffness *= kCreaseBendingShare;
        if (!(stiffness > 0.0)) return;
        st.compliance = 1.0 / stiffness;
        out.push_back(st);
    };

    const Grid g = findGrid(sheet);
    if (g.rows > 0) {
        // The plate's energy ½ D ∫ |a|² + |b|² + 2ν a·b + 2(1 − ν)|c|² dA with a, b the
        // second derivatives of x along the two grid directions and c the mixed one,
        // by finite differences at each grid vertex, written as sums of squares:
        // (1 − ν)(|a|² + |b|²) + ν |a + b|². The Gaussian-curvature part matters at the
        // free edges: without it a narrow strip bends (1 − ν²)⁻¹ ≈ 1.6 times too easily
        // for ν → 1, which is what the edge stencils alone amount to. Along a free edge
        // only the derivative along it exists, and the edge carries no moment, which
        // leaves the beam's D (1 − ν²).
        const double nu = kPoisson;
        const auto id = [&](int r, int c) { return static_cast<Index>(r * g.columns + c); };
        const auto& pinned = sheet.verts.pinned;
        // At a clamp (a pinned vertex with pinned paper on one side and free paper on
        // the other) the pinned side fixes the tangent, so the curvature at the vertex
        // is twice the plain difference, (x_in − 2x + x_out) · 2 / h², over half a cell:
        // twice the energy. Without it the clamp sits half a cell behind its row and
        // a 5 cm cantilever droops 10 % more at 2.5 mm cells.
        const auto clampFactor = [&](Index before, Index v, Index after) {
            return pinned[v] && (pinned[before] != pinned[after]) ? 2.0 : 1.0;
        };
        for (int r = 0; r < g.rows; ++r)
            for (int c = 0; c < g.columns; ++c) {
                const bool hasA = c > 0 && c + 1 < g.columns;
                const bool hasB = r > 0 && r + 1 < g.rows;
                const double area = g.hx * g.hz * (hasA ? 1.0 : 0.5) * (hasB ? 1.0 : 0.5);
                Stencil a, b, ab, mixed;
                if (hasA) {
                    const double q = 1.0 / (g.hx * g.hx);
                    a.count = 3;
                    a.v = {id(r, c - 1), id(r, c), id(r, c + 1), kNone, kNone};
                    a.k = {q, -2.0 * q, q, 0.0, 0.0};
                }
                if (hasB) {
                    const double q = 1.0 / (g.hz * g.hz);
                    b.count = 3;
                    b.v = {id(r - 1, c), id(r, c), id(r + 1, c), kNone, kNone};
                    b.k = {q, -2.0 * q, q, 0.0, 0.0};
                }
                const double fa = hasA ? clampFactor(a.v[0], a.v[1], a.v[2]) : 1.0;
                const double fb = hasB ? clampFactor(b.v[0], b.v[1], b.v[2]) : 1.0;
                if (hasA && hasB) {
                    add(a, d * area * (1.0 - nu) * fa);
                    add(b, d * area * (1.0 - nu) * fb);
                    ab.count = 5;
                    ab.v = {id(r, c - 1), id(r, c + 1), id(r - 1, c), id(r + 1, c), id(r, c)};
                    ab.k = {a.k[0], a.k[2], b.k[0], b.k[2], a.k[1] + b.k[1]};
                    add(ab, d * area * nu);
                    const double q = 1.0 / (4.0 * g.hx * g.hz);
                    mixed.count = 4;
                    mixed.v = {id(r + 1, c + 1), id(r + 1, c - 1), id(r - 1, c + 1),
                               id(r - 1, c - 1), kNone};
                    mixed.k = {q, -q, -q, q, 0.0};
                    add(mixed, d * area * 2.0 * (1.0 - nu));
                } else if (hasA) {
                    add(a, d * area * (1.0 - nu * nu) * fa);
                } else if (hasB) {
                    add(b, d * area * (1.0 - nu * nu) * fb);
                }
            }
    }
    // Edges the grid does not cover (any edge when there is no grid; else the edges
    // around vertices a break inserted) bend by the edge stencil.
    for (Index s = 0; s < S.size(); ++s) {
        if (S.kind[s] != SpringKind::Structural) continue;
        if (g.rows > 0) {
            const Index gridVerts = static_cast<Index>(g.rows * g.columns);
            if (S.a[s] < gridVerts && S.b[s] < gridVerts) continue;
        }
        Stencil st;
        double area = 0.0;
        if (!edgeStencil(sheet, s, st, area)) continue;
        add(st, d / area);
    }
    return out;
}

// Greedy colouring in spring order (deterministic), then the constraints sorted by
// colour, stably: neighbours in a pass share no vertex, so the processor overlaps their
// square roots and divisions instead of waiting for each one's positions. Measured on
// press at 494 vertices: 2.5 times faster per sub-step than spring order. Spring order
// converges a little better per sub-step (a pull travels along a row in one pass), so
// the default sub-step count went from 32 to 40, still twice as fast as before.
void XpbdIntegrator::colourStretchConstraints(Index vertices) {
    std::vector<std::uint64_t> used(static_cast<std::size_t>(vertices), 0);
    std::vector<int> colour(stretch_.size(), kSharedColour);
    for (std::size_t q = 0; q < stretch_.size(); ++q) {
        const std::uint64_t taken = used[stretch_[q].a] | used[stretch_[q].b];
        for (int c = 0; c < kSharedColour; ++c)
            if (!(taken & (std::uint64_t{1} << c))) {
                colour[q] = c;
                used[stretch_[q].a] |= std::uint64_t{1} << c;
                used[stretch_[q].b] |= std::uint64_t{1} << c;
                break;
            }
    }
    std::vector<std::size_t> order(stretch_.size());
    for (std::size_t q = 0; q < order.size(); ++q) order[q] = q;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t x, std::size_t y) { return colour[x] < colour[y]; });
    std::vector<StretchConstraint> sorted;
    sorted.reserve(stretch_.size());
    for (std::size_t q : order) {
        sorted.push_back(stretch_[q]);
        sorted.back().colour = colour[q];
    }
    stretch_.swap(sorted);
}

void XpbdIntegrator::rebuild(Sheet& sheet, const SimParams& params) {
    const auto& S = sheet.springs;
    const Material& m = params.material;
    const std::vector<double> k = stretchStiffness(sheet, m);
    constexpr double kUnlimited = std::numeric_limits<double>::infinity();
    stretch_.clear();
    longestEdge_ = 0.0;
    for (Index s = 0; s < S.size(); ++s) {
        longestEdge_ = std::max(longestEdge_, S.rest[s]);
        const StretchConstraint base{S.a[s], S.b[s], S.rest[s], 0.0, 0.0, 0.0, 0};
        switch (S.kind[s]) {
        case SpringKind::Structural: {
            if (!(k[s] > 0.0)) break;
            StretchConstraint c = base;
            c.compliance = 1.0 / k[s];
            c.maxPush = bucklingLoad(sheet, s, m);
            c.maxPull = kUnlimited;
            stretch_.push_back(c);
            break;
        }
        case SpringKind::Crease: {
            // A crease holds the compressed length it broke at only as firmly as the
            // buckled strip it stands for: up to its buckling load either way. Held
            // rigidly, it fought the uncreased paper around it, which cannot follow a
            // shortened edge without stretching (20 % stretch next to press's creases).
            StretchConstraint c = base;
            c.compliance = 1.0 / k[s];
            c.maxPush = c.maxPull = bucklingLoad(sheet, s, m);
            stretch_.push_back(c);
            break;
        }
        case SpringKind::Hinge: {
            // A hinge keeps the flaps of a closed fold from passing through each other:
            // a hard, one-sided limit (no pull below). As a two-sided spring of the
            // paper's 100 N/m it rang undamped against the light vertices of the fold
            // (period 1.7 ms) and held 3 % stretch in press long after the tool left.
            StretchConstraint c = base;
            c.maxPush = kUnlimited;
            stretch_.push_back(c);
            break;
        }
        case SpringKind::Bending: // bending is the stencils' job here
            break;
        }
    }
    colourStretchConstraints(sheet.verts.size());
    // A fold the paper has yielded into stays when the mesh changes elsewhere, and
    // comes back from a file: the rest values are kept with the sheet, by vertices.
    std::map<std::array<Index, 5>, Vec3> kept;
    for (const PaperState::PlasticBend& p : sheet.paper.plastic) kept[p.vertices] = p.rest;
    stencils_ = bendingStencils(sheet, m);
    plastic_.assign(stencils_.size(), Vec3::Zero());
    sheet.paper.plastic.clear();
    if (!kept.empty())
        for (std::size_t q = 0; q < stencils_.size(); ++q)
            if (auto it = kept.find(stencils_[q].v); it != kept.end()) {
                plastic_[q] = it->second;
                sheet.paper.plastic.push_back({stencils_[q].v, it->second});
            }
    // Long-range attachments to the pins, not to a hand: the hand is paper held by a
    // grip (step), so the vertex it holds is tethered like any other, and the paper
    // round it to the nearest real pin. Tethered to the hand as to a pin, the paper
    // round a grab was yanked along, against the real pins' tethers (lifting the middle
    // of a sheet pinned at its corners read 1,700 % stretch with the grip, 454 % with a
    // rigid hand).
    tethers_.clear();
    const auto& V = sheet.verts;
    const Index hand = contacts_.hand;
    const auto isPin = [&](Index i) { return V.pinned[i] && i != hand; };
    std::vector<Index> pins;
    for (Index i = 0; i < V.size(); ++i)
        if (isPin(i)) pins.push_back(i);
    if (!pins.empty())
        for (Index i = 0; i < V.size(); ++i) {
            if (isPin(i)) continue;
            Tether t{i, kNone, std::numeric_limits<double>::infinity()};
            for (Index p : pins) {
                const double d = sheet.materialDistance(i, p);
                if (d < t.length) {
                    t.pin = p;
                    t.length = d;
                }
            }
            tethers_.push_back(t);
        }
    builtFor_ = m;
    factor(sheet, params);
}

void XpbdIntegrator::factor(const Sheet& sheet, const SimParams& params) {
    const auto& V = sheet.verts;
    const Index nv = V.size();
    std::vector<Eigen::Triplet<double>> entries, damped;
    entries.reserve(16 * stencils_.size());
    damped.reserve(16 * stencils_.size());
    for (const Stencil& st : stencils_) {
        const double c = 1.0 / st.compliance;
        const double share = std::min(1.0, st.span / kFullyDampedSpan);
        for (int q = 0; q < st.count; ++q)
            for (int r = 0; r < st.count; ++r) {
                entries.emplace_back(st.v[q], st.v[r], c * st.k[q] * st.k[r]);
                damped.emplace_back(st.v[q], st.v[r], share * share * c * st.k[q] * st.k[r]);
            }
    }
    bending_.resize(nv, nv);
    bending_.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseMatrix<double> damping(nv, nv); // Σ (β share²) Q_s, over β
    damping.setFromTriplets(damped.begin(), damped.end());
    // Pinned vertices follow their script: in the solve they weigh a million times more,
    // which moves them by a millionth of what bending would, and their solved velocity
    // is discarded.
    solveMass_.resize(static_cast<std::size_t>(nv));
    for (Index i = 0; i < nv; ++i) solveMass_[i] = V.pinned[i] ? 1e6 * V.m[i] + 1e-3 : V.m[i];
    const double h = solveStep(params);
    Eigen::SparseMatrix<double> a = h * h * bending_ + params.bendingDamping * h * damping;
    for (Index i = 0; i < nv; ++i) a.coeffRef(i, i) += solveMass_[i];
    factored_ = solver_.compute(a);
    factoredDt_ = h;
    factoredDamping_ = params.bendingDamping;
}

// Plastic bending: where Σ k x strays from its rest value r by more than the yield
// (κ_y in the stencil's measure), r follows it, so the elastic part never exceeds the
// yield moment D κ_y and the rest stays when the paper is let go. The energy
// ½ c |Σ k x − r|² adds the force c k_q r to vertex q, so the matrix stays the one
// already factored. r is a vector in world space: a rest value along the surface
// normal alone left the in-plane part of a sharp fold elastic, and the sheet fought
// its own pleats for seconds after the tool had left. (Σ k = 0, so r exerts no net
// force; a yielded region turned as a whole feels at most the yield moment.)
// A crease is weaker than the paper beside it: the fibres that yielded at the surfaces
// have let go. Paper bent past its yield localises the bend into a crease a few
// thicknesses wide (the material's crease spacing), and what springs back when it is
// let go is the elastic part of that narrow crease, κ_y w_c, not of a whole cell: with
// the yield moment of a cell (κ_y times 1.2 cm at the editor's resolution, a 67-degree
// turn per row) a fold that spread over two or three rows, as a fold of a doubled
// sheet does, sprang open. So the yield limit of a stencil falls, as its plastic
// curvature grows to κ_y, from κ_y to κ_y w_c / span (never above κ_y): a fold keeps
// the same angle at any resolution, and paper below its yield is as elastic as it was.
namespace {
double creaseSoftening(double plasticCurvature, double span, const Material& m) {
    const double creased = span > m.creaseSpacing ? m.creaseSpacing / span : 1.0;
    return std::max(creased, 1.0 - plasticCurvature / m.yieldCurvature);
}
} // namespace

void XpbdIntegrator::yieldPlastically(Sheet& sheet, const Material& m) {
    const auto& V = sheet.verts;
    plasticForce_.assign(static_cast<std::size_t>(V.size()), Vec3::Zero());
    anyPlastic_ = false;
    bool yielded = false;
    for (std::size_t q = 0; q < stencils_.size(); ++q) {
        const Stencil& st = stencils_[q];
        Vec3 y = Vec3::Zero();
        for (int k = 0; k < st.count; ++k) y += st.k[k] * V.x[st.v[k]];
        Vec3& r = plastic_[q];
        const Vec3 elastic = y - r;
        const double yield =
            m.yieldCurvature * st.unit * creaseSoftening(r.norm() / st.unit, st.span, m);
        const double size2 = elastic.squaredNorm();
        if (size2 > yield * yield) {
            r = y - elastic * (yield / std::sqrt(size2));
            yielded = true;
        }
        if (r == Vec3::Zero()) continue;
        anyPlastic_ = true;
        const Vec3 f = r / st.compliance;
        for (int k = 0; k < st.count; ++k) plasticForce_[st.v[k]] += st.k[k] * f;
    }
    if (!yielded) return;
    auto& kept = sheet.paper.plastic;
    kept.clear();
    for (std::size_t q = 0; q < stencils_.size(); ++q)
        if (plastic_[q] != Vec3::Zero()) kept.push_back({stencils_[q].v, plastic_[q]});
}

// Backward Euler for gravity and the bending force f = -Q x (plus the plastic rest) over
// h, kSubstepsPerBendingSolve sub-steps: (M + (h² + βh) Q) v' = M v + h M g - h Q x.
// It runs before the stretch pass of the first of those sub-steps, so that bending and
// stretch meet as forces in small steps (kSubstepsPerBendingSolve says why). The last
// group of a step whose sub-steps are not a multiple of it is shorter: h is then
// smaller than the factored matrix's, which only damps that group's bending a little.
// Gravity is inside the same solve: added separately, the velocity it left met the
// damping term and a clamped strip sank by 0.32 mm.
void XpbdIntegrator::bendImplicitly(Sheet& sheet, const Vec3& g, double h) {
    auto& V = sheet.verts;
    const Index nv = V.size();
    if (!factored_ || nv == 0) {
        for (Index i = 0; i < nv; ++i)
            if (!V.pinned[i]) V.v[i] += h * g;
        return;
    }
    rhs_.resize(static_cast<std::size_t>(nv));
    multiplyEachCoordinate(bending_, V.x, sol_); // Q x
    for (Index i = 0; i < nv; ++i) rhs_[i] = solveMass_[i] * V.v[i] + h * V.m[i] * g - h * sol_[i];
    if (anyPlastic_)
        for (Index i = 0; i < nv; ++i) rhs_[i] += h * plasticForce_[i];
    solver_.solve(rhs_, sol_);
    for (Index i = 0; i < nv; ++i)
        if (!V.pinned[i]) V.v[i] = sol_[i];
}

// Fast projection (Goldenthal et al. 2007, "Efficient simulation of inextensible
// cloth"): after the sub-steps, every edge still stretched is brought back to its rest
// length by Newton steps on the constraints together, (J W Jᵀ) δλ = C, x −= W Jᵀ δλ.
// One sparse solve reaches across the sheet, where a Gauss-Seidel pass moves a pull
// one edge: near a clamp or under the tool's grip the sub-steps alone left 1-3 %
// stretch. Compressed edges are left to the buckling cap of the sub-steps.
void XpbdIntegrator::projectStretch(Sheet& sheet, double dt, int iterations, double compliance) {
    auto& V = sheet.verts;
    const Index nv = V.size();
    // The least stretched state the iterations reached: a Newton step is kept while it
    // does not more than double the worst stretch (below), so the iterations may wander
    // above where they were, and they end there if the last does not come back.
    double best = std::numeric_limits<double>::infinity();
    // Where Newton wandered (it ran out of iterations or of halvings) and left the worst
    // over the bound, sweeps and one more start (kLeftoverSweeps says why); the state it
    // ended in is kept if they do no better. Where it gave up on purpose (a vertex of too
    // many edges, a factorisation that failed) the sub-steps keep the stretch.
    const auto endAtTheBest = [&](bool wandered) {
        double left = worstProjectedStretch(sheet);
        if (left > best) {
            V.x = bestX_;
            V.v = bestV_;
            left = best;
        }
        if (!wandered || !(left > kStretchBound) || retrying_) return;
        ended_.x = V.x;
        ended_.v = V.v;
        relaxWhatTheProjectionLeft(sheet, dt, kLeftoverSweeps);
        retrying_ = true;
        // Cleared however the second start ends (an allocation that throws included):
        // left set, no later step would get its second start.
        const struct EndRetry {
            bool& retrying;
            ~EndRetry() { retrying = false; }
        } endRetry{retrying_};
        projectStretch(sheet, dt, iterations, compliance);
        double again = worstProjectedStretch(sheet);
        if (again > left) {
            V.x = ended_.x;
            V.v = ended_.v;
            again = left;
        }
        if (!(again > kStretchBound)) return;
        // Newton wandered from its second start too: the sweeps alone, as long as they
        // take (kStubbornSweeps says why), kept if they do better.
        ended_.x = V.x;
        ended_.v = V.v;
        relaxWhatTheProjectionLeft(sheet, dt, kStubbornSweeps);
        if (worstProjectedStretch(sheet) > again) {
            V.x = ended_.x;
            V.v = ended_.v;
        }
    };
    for (int iteration = 0; iteration < kMaxProjectionIterations; ++iteration) {
        active_.clear();
        for (std::size_t q = 0; q < stretch_.size(); ++q) {
            const StretchConstraint& k = stretch_[q];
            if (!projects(k)) continue;
            const double len = (V.x[k.a] - V.x[k.b]).norm();
            if (len > k.rest * (1.0 - kBuckledStrain)) active_.push_back(q);
        }
        if (active_.empty()) return; // nothing stretched: no state was better
        double worst = 0.0;
        for (std::size_t q : active_) {
            const StretchConstraint& k = stretch_[q];
            worst = std::max(worst, (V.x[k.a] - V.x[k.b]).norm() / k.rest - 1.0);
        }
        if (!(worst > kProjectedStretch)) return; // below every earlier iteration's
        if (worst < best) {
            best = worst;
            bestX_ = V.x;
            bestV_ = V.v;
        }
        // Past `iterations` the projection goes on only while the stretch is over issue
        // 9's bound (kMaxProjectionIterations says why), in the best state it has reached:
        // it ends there. Going on while only the current state was over it, iterations
        // that swung between two light crease vertices ran all 48 and then went back to
        // what the sixth had reached (pushing paper pinned at two corners: 8.1 Newton
        // iterations a step, up to 96 in one).
        if (iteration >= iterations && !(best > kStretchBound)) {
            endAtTheBest(false);
            return;
        }
        const Index na = static_cast<Index>(active_.size());
        dir_.resize(active_.size());
        ends_.resize(active_.size());
        Eigen::VectorXd c(na);
        // Which active constraints meet at each vertex, with the sign of the vertex in
        // each (+1 for a, -1 for b).
        incidentStart_.assign(static_cast<std::size_t>(nv) + 1, 0);
        for (std::size_t e = 0; e < active_.size(); ++e) {
            const StretchConstraint& k = stretch_[active_[e]];
            const Vec3 d = V.x[k.a] - V.x[k.b];
            const double len = d.norm();
            dir_[e] = d / len;
            ends_[e] = {k.a, k.b};
            c[static_cast<Index>(e)] = len - k.rest;
            ++incidentStart_[k.a + 1];
            ++incidentStart_[k.b + 1];
        }
        for (Index i = 0; i < nv; ++i)
            if (w_[i] != 0.0 && incidentStart_[i + 1] > kMaxProjectedDegree) {
                endAtTheBest(false);
                return;
            }
        for (Index i = 0; i < nv; ++i) incidentStart_[i + 1] += incidentStart_[i];
        incident_.resize(incidentStart_[nv]);
        std::vector<Index> fill(incidentStart_.begin(), incidentStart_.end() - 1);
        for (std::size_t e = 0; e < active_.size(); ++e) {
            const StretchConstraint& k = stretch_[active_[e]];
            incident_[fill[k.a]++] = {static_cast<Index>(e), 1.0};
            incident_[fill[k.b]++] = {static_cast<Index>(e), -1.0};
        }
        // A triangle mesh has more edges than its vertices have free directions where
        // pins hold it, so J W Jᵀ is singular there: a small diagonal term (a
        // compliance) keeps the solve well posed, and a larger one damps the step
        // (kDampedProjectionCompliance).
        assembleProjectionSystem(ends_, dir_, w_, incidentStart_, incident_, compliance,
                                 projectionSystem_);
        projection_.compute(projectionSystem_);
        if (projection_.info() != Eigen::Success) {
            endAtTheBest(false);
            return;
        }
        ++projectionWork_.newtonIterations;
        const Eigen::VectorXd lambda = projection_.solve(c);
        // The Newton step, halved while it more than doubles the worst stretch: on the
        // slivers breaks insert along a fold, J W Jᵀ is nearly singular and the full
        // step diverged (a second fold's stretch went 69 %, 229 %, 366 % in three
        // iterations). If no shorter step holds, the projection ends (at its best state). A
        // step that merely fails to shrink the worst is kept: requiring that made the
        // soft (×1) drape of the stability map blow up at h = 1/7680 s.
        projectedFrom_ = V.x;
        velocityFrom_ = V.v;
        double fraction = 1.0;
        for (int halving = 0;; ++halving) {
            for (std::size_t e = 0; e < active_.size(); ++e) {
                const StretchConstraint& k = stretch_[active_[e]];
                const Vec3 move = dir_[e] * (fraction * lambda[static_cast<Index>(e)]);
                V.x[k.a] -= w_[k.a] * move;
                V.x[k.b] += w_[k.b] * move;
                V.v[k.a] -= w_[k.a] * move / dt;
                V.v[k.b] += w_[k.b] * move / dt;
            }
            // (A NaN from an overflowing solve fails the test and is undone too.)
            const double after = worstProjectedStretch(sheet);
            if (after <= kProjectionDivergence * worst) {
                // A damped step that barely shrinks the worst stretch has met what the
                // damping is not for: stiff, nearly dependent edges round light vertices
                // (a crumpled sheet between still pins: each iteration took 4 % off the
                // worst, and the sixteenth left 0.9 %). The undamped step takes the rest.
                if (iteration >= kDampedIterationsBeforeFallback &&
                    compliance > kProjectionCompliance && !(after < kSlowDampedProgress * worst))
                    compliance = kProjectionCompliance;
                break;
            }
            V.x = projectedFrom_;
            V.v = velocityFrom_;
            if (halving == kProjectionHalvings) {
                endAtTheBest(true);
                return;
            }
            fraction *= 0.5;
        }
    }
    endAtTheBest(true);
}

// The projection leaves the paper within kProjectedStretch, and the tool then pushes out
// what lies inside it. Paper drawn taut under it (a sheet pinned at two corners, rolled
// by one stroke and pressed by the next) cannot make way: the push stretched it 1.1-1.5 %
// after every step, over issue 9's 1 %. Real paper pulled taut stops a hand that pushes
// into it, so the tool stops short instead: at the furthest point of its move in this
// step at which pushing the paper out of it stretches the paper no more than the
// projection left it (or kProjectedStretch), found by bisection.
void XpbdIntegrator::holdToolWhereThePaperIsTaut(const Vec3& from,
                                                 const std::function<void(const Vec3&)>& pushOut,
                                                 bool toolInThePaper, Sheet& sheet) {
    const SphereTool& sp = contacts_.sphere;
    if (!toolInThePaper) {
        pushOut(sp.center);
        return;
    }
    auto& x = sheet.verts.x;
    const double allowed = std::max(worstProjectedStretch(sheet), kProjectedStretch);
    beforeTool_ = x;
    pushOut(sp.center);
    if (!(worstProjectedStretch(sheet) > allowed)) return;
    // The bisection starts where the paper lets the tool be. That is where the step began,
    // unless the paper has come into the tool there since: the projection pulls back what
    // the sub-steps stretched round the tool, and a hanging sheet swings back against it.
    // Pushed out from there, taut paper stretched 1-16 % after the step (a sheet hanging
    // from two pins, pushed in the editor). The paper then pushes the tool back, out of it
    // along the way from the paper inside it to its centre: as far as the deepest paper
    // lies in it, or two, four times as far, up to twice its radius.
    x = beforeTool_;
    pushOut(from);
    Vec3 start = from;
    if (worstProjectedStretch(sheet) > allowed) {
        Vec3 inside = Vec3::Zero(); // the paper inside, weighted by its depth
        double depths = 0.0, deepest = 0.0;
        for (Index t : toolTriangles_) {
            const auto& tv = sheet.tris[t].v;
            const Vec3 b = closestPointBarycentric(beforeTool_[tv[0]], beforeTool_[tv[1]],
                                                   beforeTool_[tv[2]], from);
            const Vec3 q =
                b[0] * beforeTool_[tv[0]] + b[1] * beforeTool_[tv[1]] + b[2] * beforeTool_[tv[2]];
            const double depth = sp.radius - (q - from).norm();
            if (depth > 0.0) {
                inside += depth * q;
                depths += depth;
                deepest = std::max(deepest, depth);
            }
        }
        const Vec3 away = depths > 0.0 ? Vec3(from - inside / depths) : Vec3::Zero();
        if (away.norm() > 0.0) {
            // Moved twice its radius, the tool holds none of the paper it held.
            for (double d = deepest;; d = std::min(2.0 * d, 2.0 * sp.radius)) {
                const Vec3 back = from + away.normalized() * d;
                x = beforeTool_;
                pushOut(back);
                if (!(worstProjectedStretch(sheet) > allowed)) {
                    start = back;
                    break;
                }
                if (d == 2.0 * sp.radius) break;
            }
        }
    }
    double reached = 0.0, tooFar = 1.0;
    for (int k = 0; k < kToolHoldBisections; ++k) {
        const double mid = 0.5 * (reached + tooFar);
        x = beforeTool_;
        pushOut(start + mid * (sp.center - start));
        (worstProjectedStretch(sheet) > allowed ? tooFar : reached) = mid;
    }
    toolHeldAt_ = start + reached * (sp.center - start);
    x = beforeTool_;
    pushOut(*toolHeldAt_);
}

// kLeftoverSweeps says why. Mass-weighted, as the projection moves, and the move is a
// change of velocity too, as the projection's is.
void XpbdIntegrator::relaxWhatTheProjectionLeft(Sheet& sheet, double dt, int sweeps) {
    auto& V = sheet.verts;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        double worst = 0.0;
        for (const StretchConstraint& k : stretch_) {
            if (!projects(k)) continue;
            const Vec3 d = V.x[k.a] - V.x[k.b];
            const double len = d.norm();
            const double excess = len - k.rest;
            if (!(excess > 0.0)) continue;
            worst = std::max(worst, excess / k.rest);
            const Vec3 move = d * (excess / (len * (w_[k.a] + w_[k.b])));
            V.x[k.a] -= w_[k.a] * move;
            V.x[k.b] += w_[k.b] * move;
            V.v[k.a] -= w_[k.a] * move / dt;
            V.v[k.b] += w_[k.b] * move / dt;
        }
        if (!(worst > kProjectedStretch)) return;
    }
}

// The largest stretch among the edges the projection holds.
double XpbdIntegrator::worstProjectedStretch(const Sheet& sheet) const {
    const auto& V = sheet.verts;
    double worst = 0.0;
    for (const StretchConstraint& k : stretch_)
        if (projects(k)) worst = std::max(worst, (V.x[k.a] - V.x[k.b]).norm() / k.rest - 1.0);
    return worst;
}

namespace {

// Whether a pinned vertex other than `except` moves in this step.
bool aPinMoves(const Vertices& V, Index except) {
    for (Index i = 0; i < V.size(); ++i)
        if (V.pinned[i] && i != except && V.v[i] != Vec3::Zero()) return true;
    return false;
}

} // namespace

bool XpbdIntegrator::mustWake(const Sheet& sheet) const {
    const auto& V = sheet.verts;
    if (aPinMoves(V, kNone)) return true;
    const SphereTool& sp = contacts_.sphere;
    if (!sp.active || sp.velocity.squaredNorm() == 0.0) return false;
    const double reach = sp.radius + kToolReach + 0.01;
    for (Index i = 0; i < V.size(); ++i)
        if ((V.x[i] - sp.center).squaredNorm() < reach * reach) return true;
    return false;
}

namespace {

// Whether every free vertex's `at` lies within `reach` of its `from` (one per vertex).
bool stayedWithin(const Vertices& V, const std::vector<Vec3>& at, const std::vector<Vec3>& from,
                  double reach) {
    if (from.size() != V.x.size() || at.size() != V.x.size()) return false;
    const double reach2 = reach * reach;
    for (Index i = 0; i < V.size(); ++i)
        if (!V.pinned[i] && (at[i] - from[i]).squaredNorm() > reach2) return false;
    return true;
}

} // namespace

void XpbdIntegrator::advance(Sheet& sheet, const SimParams& params) {
    toolHeldAt_.reset();
    auto& V = sheet.verts;
    const auto& S = sheet.springs;
    const Index nv = V.size();
    std::int64_t active = 0;
    for (const DamageEvent& ev : sheet.events) active += ev.active ? 1 : 0;
    // Which vertices are pinned, not only how many: the user pins and unpins (FNV-1a).
    std::int64_t pins = 0;
    std::uint64_t pinHash = 14695981039346656037ull;
    for (Index i = 0; i < nv; ++i)
        if (V.pinned[i]) {
            ++pins;
            pinHash = (pinHash ^ static_cast<std::uint64_t>(i)) * 1099511628211ull;
        }
    // The hand too: the tethers leave it out (rebuild).
    const std::array<std::int64_t, 8> signature{nv,
                                                S.size(),
                                                sheet.triangleCount(),
                                                static_cast<std::int64_t>(sheet.events.size()),
                                                active,
                                                pins,
                                                static_cast<std::int64_t>(pinHash),
                                                contacts_.hand};
    // A changed mesh or paper has already let the tool go and woken the sheet
    // (PaperState::meshChanged, where the change was made).
    if (signature != signature_ || !(builtFor_ == params.material)) {
        rebuild(sheet, params);
        signature_ = signature;
    } else if (solveStep(params) != factoredDt_ || params.bendingDamping != factoredDamping_) {
        factor(sheet, params);
    }
    PaperState& paper = sheet.paper;
    const int stillStepsBeforeSleep =
        static_cast<int>(std::ceil(kSecondsStillBeforeSleep / params.dt - 1e-9));
    const auto sleepy = [&] {
        return paper.quietSteps >= kStepsBeforeSleep ||
               paper.still.steps >= stillStepsBeforeSleep ||
               paper.slowStill.steps >= stillStepsBeforeSleep;
    };
    const auto stopFreeVertices = [&] {
        for (Index i = 0; i < nv; ++i)
            if (!V.pinned[i]) V.v[i] = Vec3::Zero();
    };
    const Vec3 g =
        params.gravity * Vec3(std::sin(params.gravityTilt), -std::cos(params.gravityTilt), 0.0);
    // A sheet at rest under one gravity is not at rest under another: a load ramped up
    // from nothing (the cantilever check) left a stiff strip asleep, flat, under the
    // whole of it. So a change wakes the sheet and, while it goes on, keeps it awake. A
    // sheet's first step here (a new one, or one loaded asleep from a file) has no
    // earlier gravity to differ from.
    const bool gravityChanged = lastGravity_ && *lastGravity_ != g;
    lastGravity_ = g;
    asleep_ = sleepy();
    if (asleep_) {
        if (!mustWake(sheet) && !gravityChanged) {
            stopFreeVertices();
            return;
        }
        asleep_ = false;
        sheet.paper.wake();
    }

    const int n = std::max(1, params.substeps);
    const double h = params.dt / n;
    const double h2 = h * h;
    const Material& mat = params.material;
    w_.resize(static_cast<std::size_t>(nv));
    for (Index i = 0; i < nv; ++i) w_[i] = V.pinned[i] || !(V.m[i] > 0.0) ? 0.0 : 1.0 / V.m[i];
    // The vertex a hand holds is pinned for the bending solve and for sleep, but in the
    // sub-steps it is paper like any other, held to the hand's path (its pinned velocity
    // over the step) by a force-limited grip.
    const Index hand = contacts_.hand;
    const bool holding = hand >= 0 && hand < nv && V.pinned[hand] && V.m[hand] > 0.0;
    const Vec3 handFrom = holding ? V.x[hand] : Vec3::Zero();
    const Vec3 handVelocity = holding ? V.v[hand] : Vec3::Zero();
    if (holding) w_[hand] = 1.0 / V.m[hand];
    // Paper driven by pins that move (the Fold tool's carry, a hand, a scene's script)
    // turns as they take it; while the tool is pressed, the paper's shape is the user's.
    const SphereTool& sp = contacts_.sphere;
    if (!aPinMoves(V, kNone))
        dragThroughAir(sheet, mat.arealDensity, g, params.dt, airNormals_, sp.active);
    xPrev_.resize(static_cast<std::size_t>(nv));
    stepStart_ = V.x;
    const Vec3 sphereStart = sp.center - sp.velocity * params.dt;

    // Position-level Coulomb friction: the tangential slip of this sub-step is undone
    // while it is within μs times the normal correction, else cut by μk times it.
    const auto friction = [](Vec3& x, const Vec3& slip, double push, double mus, double muk) {
        const double len = slip.norm();
        if (len <= mus * push) {
            x -= slip;
        } else if (len > 0.0) {
            x -= slip * std::min(1.0, muk * push / len);
        }
    };
    // The tool grips the paper within kToolReach of its surface: a rigid sphere that
    // stops half a millimetre above the desk still presses the paper lying on it.
    // Where the tool and the desk hold the same vertex, the tool's friction, the larger
    // (μ_tool > μ_desk), decides the slide, and the desk only keeps it above itself.
    touched_.assign(static_cast<std::size_t>(nv), 0);
    onDesk_.assign(static_cast<std::size_t>(nv), 0);
    deskImpulse_.assign(static_cast<std::size_t>(nv), 0.0);
    // The tool touches the paper's triangles, not only its vertices: a sphere resting
    // on the desk meets the sheet in a patch a few millimetres wide, smaller than a
    // cell, and would otherwise slide over the paper between vertices without holding
    // it. Triangles that can come within reach during this step are found once.
    toolTriangles_.clear();
    if (sp.active) {
        const double travel = sp.velocity.norm() * params.dt;
        const double near = sp.radius + kToolReach + travel + longestEdge_ + 0.01;
        const double near2 = near * near;
        for (Index t = 0; t < sheet.triangleCount(); ++t) {
            const auto& tv = sheet.tris[t].v;
            if ((V.x[tv[0]] - sp.center).squaredNorm() < near2 ||
                (V.x[tv[1]] - sp.center).squaredNorm() < near2 ||
                (V.x[tv[2]] - sp.center).squaredNorm() < near2)
                toolTriangles_.push_back(t);
        }
    }
    // The tool presses the paper onto the desk with params.toolForce and holds it there
    // by friction, at most (μ_tool − μ_desk) times that force, shared by the triangles
    // under it. Each
    // held triangle is tied to the point of the tool where it was caught by a soft
    // XPBD constraint (kGripCompliance): a hard, position-level grip transmitted any
    // force at all, and pulled the paper between the tool and a held edge 20-50 %
    // long; a grip applied only as sub-step friction moved nothing but the three light
    // vertices it touched, and the tool slid over a sheet it pressed onto the desk.
    auto& grips = sheet.paper.grips;
    if (!sp.active) grips.clear();
    const auto grip = [&](Index t, const Vec3& b, const Vec3& offset) {
        for (const PaperState::ToolGrip& g : grips)
            if (g.triangle == t) return;
        grips.push_back({t, b, offset});
    };
    const auto pullWithTool = [&](const Vec3& c) {
        const double reach = sp.radius + kToolReach;
        const auto pointOf = [&](const PaperState::ToolGrip& g) {
            const auto& tv = sheet.tris[g.triangle].v;
            return Vec3(g.barycentric[0] * V.x[tv[0]] + g.barycentric[1] * V.x[tv[1]] +
                        g.barycentric[2] * V.x[tv[2]]);
        };
        // The tool lets go of what has left its lower cap.
        std::erase_if(grips, [&](const PaperState::ToolGrip& g) {
            const Vec3 d = pointOf(g) - c;
            return !(d.squaredNorm() < reach * reach) || !(d.y() < -0.7 * d.norm());
        });
        if (grips.empty()) return;
        const double share = params.toolForce / static_cast<double>(grips.size());
        const double alpha = kGripCompliance / h2;
        // The desk under the paper holds it back by its own friction times the same
        // force, so what is left to drag the sheet is the difference.
        const double holds = std::max(0.0, mat.toolStaticFriction - mat.groundKineticFriction);
        const double drags = std::max(0.0, mat.toolKineticFriction - mat.groundKineticFriction);
        for (PaperState::ToolGrip& g : grips) {
            const auto& tv = sheet.tris[g.triangle].v;
            const Vec3 d = pointOf(g) - c;
            const double wsum = w_[tv[0]] * g.barycentric[0] * g.barycentric[0] +
                                w_[tv[1]] * g.barycentric[1] * g.barycentric[1] +
                                w_[tv[2]] * g.barycentric[2] * g.barycentric[2];
            Vec3 e = d - g.offset;
            e.y() = 0.0; // across the desk; the tool presses along y
            const double len = e.norm();
            if (!(wsum > 0.0) || !(len > 0.0)) continue;
            double lambda = len / (wsum + alpha);
            if (lambda > holds * share * h2) {
                // Sliding: kinetic friction, and the tool holds on where the paper will
                // be after this correction, d − e λ wsum / len.
                lambda = std::min(lambda, drags * share * h2);
                g.offset = d - e * (lambda * wsum / len);
            }
            const Vec3 step = e * (-lambda / len);
            for (int k = 0; k < 3; ++k) V.x[tv[k]] += (w_[tv[k]] * g.barycentric[k]) * step;
        }
    };
    const auto collideSphere = [&](const Vec3& c, const Vec3& cPrev, bool withFriction) {
        const double reach = sp.radius + kToolReach;
        for (Index t : toolTriangles_) {
            const auto& tv = sheet.tris[t].v;
            // The triangle lies in its bounding box: if the box is out of reach, so is
            // the triangle (with room for rounding). Most triangles near the tool are
            // (the closest point was 8 % of press's step; 2 % of them are in reach).
            const Vec3 lo = V.x[tv[0]].cwiseMin(V.x[tv[1]]).cwiseMin(V.x[tv[2]]);
            const Vec3 hi = V.x[tv[0]].cwiseMax(V.x[tv[1]]).cwiseMax(V.x[tv[2]]);
            if ((c.cwiseMax(lo).cwiseMin(hi) - c).squaredNorm() > 1.000001 * reach * reach)
                continue;
            const double w0 = w_[tv[0]], w1 = w_[tv[1]], w2 = w_[tv[2]];
            const Vec3 b = closestPointBarycentric(V.x[tv[0]], V.x[tv[1]], V.x[tv[2]], c);
            const Vec3 q = b[0] * V.x[tv[0]] + b[1] * V.x[tv[1]] + b[2] * V.x[tv[2]];
            const Vec3 d = q - c;
            const double dist2 = d.squaredNorm();
            if (!(dist2 < reach * reach)) continue;
            const double wsum = w0 * b[0] * b[0] + w1 * b[1] * b[1] + w2 * b[2] * b[2];
            if (!(wsum > 0.0)) continue;
            const double dist = std::sqrt(dist2);
            const Vec3 nrm = dist > 1e-12 ? Vec3(d / dist) : Vec3::UnitY();
            // The tool's hard surface is at its radius; its lower cap, which presses the
            // paper onto the desk, also grips what lies within kToolReach below it (a
            // fingertip's soft skin; the step keeps the sphere above the desk).
            const bool onDesk =
                contacts_.ground && q.y() < contacts_.groundHeight + 2.0 * kToolReach;
            if (nrm.y() < -0.7 && withFriction && onDesk) grip(t, b, q - c);
            if (!(dist < sp.radius)) continue;
            const double push = sp.radius - dist;
            Vec3 move = push * nrm;
            if (withFriction) {
                const Vec3 qPrev =
                    b[0] * xPrev_[tv[0]] + b[1] * xPrev_[tv[1]] + b[2] * xPrev_[tv[2]];
                const Vec3 rel = (q - qPrev) - (c - cPrev);
                const Vec3 slip = rel - rel.dot(nrm) * nrm;
                const double len = slip.norm();
                const double mus = mat.toolStaticFriction, muk = mat.toolKineticFriction;
                if (len <= mus * push)
                    move -= slip;
                else if (len > 0.0)
                    move -= slip * std::min(1.0, muk * push / len);
            }
            // Moving each vertex by w_i b_i / Σ w b² of the correction moves the contact
            // point by exactly the correction.
            for (int k = 0; k < 3; ++k) {
                if (w_[tv[k]] == 0.0 || b[k] == 0.0) continue;
                V.x[tv[k]] += (w_[tv[k]] * b[k] / wsum) * move;
                touched_[tv[k]] = 1;
            }
        }
    };
    const auto holdByHand = [&](int sub) {
        if (!holding) return;
        const Vec3 e = V.x[hand] - (handFrom + handVelocity * (h * (sub + 1)));
        const double len = e.norm();
        if (!(len > 0.0)) return;
        const double lambda = std::min(len / (w_[hand] + kGripCompliance / h2), kHandForce * h2);
        V.x[hand] -= (w_[hand] * lambda / len) * e;
    };
    // `over` is the time the push's change of velocity is spread over: a sub-step's, or
    // the whole step's after the projection.
    const auto collideGround = [&](bool withFriction, double over) {
        if (!contacts_.ground) return;
        const double gh = contacts_.groundHeight;
        for (Index i = 0; i < nv; ++i) {
            if (w_[i] == 0.0 || !(V.x[i].y() < gh)) continue;
            const double push = gh - V.x[i].y();
            V.x[i].y() = gh;
            onDesk_[i] = 1;
            deskImpulse_[i] += V.m[i] * push / over;
            if (touched_[i] || !withFriction) continue;
            Vec3 slip = V.x[i] - xPrev_[i];
            slip.y() = 0.0;
            friction(V.x[i], slip, push, mat.groundStaticFriction, mat.groundKineticFriction);
        }
    };

    // What each stretch constraint needs in the sub-steps, worked out once per step:
    // its inverse masses, its XPBD gain 1 / (w_a + w_b + α/h²) and the correction its
    // largest pull and push allow (a division per constraint and step instead of one
    // per constraint and pass: the sub-step loop waited on it).
    stretchStep_.clear();
    for (const StretchConstraint& k : stretch_) {
        const double wsum = w_[k.a] + w_[k.b];
        if (wsum == 0.0) continue;
        stretchStep_.add({k.a, k.b, w_[k.a], w_[k.b], k.rest, 1.0 / (wsum + k.compliance / h2),
                          -k.maxPull * h2, k.maxPush * h2},
                         k.colour, k.colour == kSharedColour);
    }
    // The layers that can meet in this step: the pairs that can touch before any vertex
    // has moved farther than twice its travel in a step (at the speed it starts with and
    // what gravity adds) plus kContactMargin.
    const bool selfContact = params.selfContact && mat.thickness > 0.0;
    if (selfContact) {
        allowance_.resize(static_cast<std::size_t>(nv));
        for (Index i = 0; i < nv; ++i)
            allowance_[i] =
                std::min(2.0 * (V.v[i].norm() + g.norm() * params.dt) * params.dt + kContactMargin,
                         kMaxContactAllowance);
        selfContact_.find(sheet, w_, mat.thickness, allowance_, kContactApart * mat.creaseSpacing);
    }
    const auto touchLayers = [&](bool withFriction) {
        if (selfContact)
            selfContact_.resolve(V.x, xPrev_, w_, mat.paperStaticFriction, mat.paperKineticFriction,
                                 withFriction, kContactSeparationSpeed * h);
    };
    yieldPlastically(sheet, mat);
    for (int sub = 0; sub < n; ++sub) {
        if (sub % kSubstepsPerBendingSolve == 0)
            bendImplicitly(sheet, g, h * std::min(kSubstepsPerBendingSolve, n - sub));
        for (Index i = 0; i < nv; ++i) {
            xPrev_[i] = V.x[i];
            V.x[i] += h * V.v[i];
        }
        const Vec3 c = sphereStart + sp.velocity * (h * (sub + 1));
        const Vec3 cPrev = c - sp.velocity * h;
        // Contacts with friction first, on the predicted motion, so that the stretch
        // pass after them is not undone by friction (that left 7 % stretch in press);
        // then the layers, the desk and the tool once more without friction, the desk
        // last, so that nothing ends a sub-step inside either.
        std::fill(touched_.begin(), touched_.end(), std::uint8_t{0});
        collideSphere(c, cPrev, true);
        pullWithTool(c);
        holdByHand(sub);
        collideGround(true, h);
        touchLayers(true);
        stretchStep_.relax(V.x);
        // Long-range attachments (Kim et al. 2012): no vertex gets farther from its
        // nearest pinned vertex than the paper between them allows, so a hanging sheet
        // holds its length without the pull walking one edge per pass from the pins.
        for (const Tether& t : tethers_) {
            if (w_[t.vertex] == 0.0) continue; // the sub-steps do not move it (pinned, not held)
            const Vec3 d = V.x[t.vertex] - V.x[t.pin];
            const double len = d.norm();
            if (len > t.length) V.x[t.vertex] = V.x[t.pin] + d * (t.length / len);
        }
        // The stretch pass and the tethers can pull a vertex back into the layer under
        // it: a light corner of a layer landing on another ended its step 0.4 of the
        // thickness into it once the air slowed the layer's flutter.
        touchLayers(false);
        collideSphere(c, cPrev, false);
        collideGround(false, h);
        collideSphere(c, cPrev, false);
        collideGround(false, h);
        for (Index i = 0; i < nv; ++i)
            if (w_[i] != 0.0) V.v[i] = (V.x[i] - xPrev_[i]) / h;
    }

    // The projection is damped (kDampedProjectionCompliance) where paper hangs from what
    // holds it: pinned or held by the hand (`pins` counts the hand's vertex too), every
    // pin standing still in this step, and the tool not in the paper. Pins that carry the
    // paper (the Fold tool's flap, `compress`'s edges, while they move) and the tool keep
    // the undamped step, whose overshoot their scenes' breaks and folds were measured
    // with. It reads only what a saved sheet keeps, so a loaded sheet resumes exactly.
    const bool toolInThePaper = (sp.active && !toolTriangles_.empty()) || !grips.empty();
    const bool hanging = pins > 0 && !aPinMoves(V, hand) && !toolInThePaper;
    // (Only paper is projected: kPaperStiffness says why.)
    if (mat.stretchStiffness >= kPaperStiffness)
        projectStretch(sheet, params.dt, kProjectionIterations,
                       hanging ? kDampedProjectionCompliance : kProjectionCompliance);
    holdToolWhereThePaperIsTaut(
        sphereStart, [&](const Vec3& c) { collideSphere(c, c, false); }, toolInThePaper, sheet);
    collideGround(false, params.dt);
    // Coulomb's law for the sheet as a whole (sim/DeskHold.h): on the desk alone, or
    // hanging from one still pin onto it. Neither while a tool, a grip or a hand acts.
    const bool deskWithoutTool =
        contacts_.ground && (!sp.active || toolTriangles_.empty()) && grips.empty();
    const DeskHoldScene desk{g, params.dt, mat.groundKineticFriction};
    const Pivot pivot = deskWithoutTool && pins > 0 ? pivotOf(V) : Pivot{};
    if (deskWithoutTool && pins == 0)
        holdOnDesk(V, stepStart_, onDesk_, desk, paper.deskSlide);
    else if (deskWithoutTool && hand < 0 && pivot.kind == Pivot::Kind::Point &&
             !aPinMoves(V, kNone))
        holdTurnOnDesk(V, pivot.point, stepStart_, deskImpulse_, desk, paper.deskSlide);
    else
        paper.deskSlide = kSlideUnknown;

    // Quiet is judged on where each vertex went over the whole step, not on its
    // velocity after the last sub-step: a folded sheet whose positions stayed the same
    // to 0.1 mm for minutes kept a sub-step cycle of 2 cm/s on the vertices of its fold
    // and never came to rest. Nor only on each step's move: a sheet folded twice moved
    // one vertex of its fold 0.05-0.16 mm a step, in a cycle of about three steps
    // between the sub-steps and the projection, and went nowhere (docs/material.md,
    // "Sleep").
    constexpr double kQuietSpeed = 5e-4; // m/s
    const bool quiet = stayedWithin(V, V.x, stepStart_, kQuietSpeed * params.dt);
    const auto averageAndRead = [&](PaperState::StillWatch& watch, double averaging) {
        if (watch.mean.size() != V.x.size()) {
            watch.mean = V.x;
        } else {
            for (Index i = 0; i < nv; ++i) watch.mean[i] += averaging * (V.x[i] - watch.mean[i]);
        }
        return stayedWithin(V, watch.mean, watch.from, kStillReach);
    };
    const bool still = averageAndRead(paper.still, kStillAveraging);
    const bool slowStill = averageAndRead(paper.slowStill, kSlowStillAveraging);
    // (Only asked of a sheet that kept still: it looks at every vertex and the tool.)
    const bool undisturbed = (quiet || still || slowStill) && !gravityChanged && !mustWake(sheet);
    paper.quietSteps = quiet && undisturbed ? paper.quietSteps + 1 : 0;
    for (auto [watch, kept] : {std::pair{&paper.still, still}, {&paper.slowStill, slowStill}}) {
        if (kept && undisturbed) {
            ++watch->steps;
        } else {
            watch->steps = 0;
            watch->from = watch->mean;
        }
    }
    if (sleepy()) {
        asleep_ = true;
        stopFreeVertices();
    }
}

} // namespace pf
