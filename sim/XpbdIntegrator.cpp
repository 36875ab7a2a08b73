#include "XpbdIntegrator.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
    constexpr int kColours = 63; // the last one takes whatever is left
    std::vector<std::uint64_t> used(static_cast<std::size_t>(vertices), 0);
    std::vector<int> colour(stretch_.size(), kColours);
    for (std::size_t q = 0; q < stretch_.size(); ++q) {
        const std::uint64_t taken = used[stretch_[q].a] | used[stretch_[q].b];
        for (int c = 0; c < kColours; ++c)
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
    for (std::size_t q : order) sorted.push_back(stretch_[q]);
    stretch_.swap(sorted);
}

void XpbdIntegrator::rebuild(const Sheet& sheet, const SimParams& params) {
    const auto& S = sheet.springs;
    const Material& m = params.material;
    const std::vector<double> k = stretchStiffness(sheet, m);
    compliance_.assign(static_cast<std::size_t>(S.size()), -1.0);
    maxPush_.assign(static_cast<std::size_t>(S.size()), 0.0);
    for (Index s = 0; s < S.size(); ++s) {
        switch (S.kind[s]) {
        case SpringKind::Structural: {
            if (!(k[s] > 0.0)) break;
            compliance_[s] = 1.0 / k[s];
            // Euler buckling of the strip the edge stands for (width (A1 + A2) / l0,
            // pinned ends): more push than this and real paper buckles out of plane
            // at a scale finer than the mesh, which is what a break stands for.
            double area = 0.0;
            for (Index t : S.faces[s])
                if (t != kNone) area += restArea(sheet, sheet.tris[t]);
            const double l0 = S.rest[s];
            maxPush_[s] =
                std::numbers::pi * std::numbers::pi * m.bendingStiffness * area / (l0 * l0 * l0);
            break;
        }
        case SpringKind::Crease:
            compliance_[s] = 1.0 / k[s];
            maxPush_[s] = std::numeric_limits<double>::infinity();
            break;
        case SpringKind::Hinge:
            compliance_[s] = 1.0 / params.stiffnessOf(SpringKind::Hinge);
            maxPush_[s] = std::numeric_limits<double>::infinity();
            break;
        case SpringKind::Bending: // bending is the stencils' job here
            break;
        }
    }
    stretch_.clear();
    for (Index s = 0; s < S.size(); ++s)
        if (compliance_[s] >= 0.0)
            stretch_.push_back({S.a[s], S.b[s], S.rest[s], compliance_[s], maxPush_[s]});
    colourStretchConstraints(sheet.verts.size());
    stencils_ = bendingStencils(sheet, m);
    tethers_.clear();
    const auto& V = sheet.verts;
    std::vector<Index> pins;
    for (Index i = 0; i < V.size(); ++i)
        if (V.pinned[i]) pins.push_back(i);
    if (!pins.empty())
        for (Index i = 0; i < V.size(); ++i) {
            if (V.pinned[i]) continue;
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
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(16 * stencils_.size());
    for (const Stencil& st : stencils_) {
        const double c = 1.0 / st.compliance;
        for (int q = 0; q < st.count; ++q)
            for (int r = 0; r < st.count; ++r)
                entries.emplace_back(st.v[q], st.v[r], c * st.k[q] * st.k[r]);
    }
    bending_.resize(nv, nv);
    bending_.setFromTriplets(entries.begin(), entries.end());
    // Pinned vertices follow their script: in the solve they weigh a million times more,
    // which moves them by a millionth of what bending would, and they are reset after.
    solveMass_.resize(static_cast<std::size_t>(nv));
    for (Index i = 0; i < nv; ++i) solveMass_[i] = V.pinned[i] ? 1e6 * V.m[i] + 1e-3 : V.m[i];
    const double h = params.dt;
    Eigen::SparseMatrix<double> a = (h * h + params.bendingDamping * h) * bending_;
    for (Index i = 0; i < nv; ++i) a.coeffRef(i, i) += solveMass_[i];
    solver_.compute(a);
    factored_ = solver_.info() == Eigen::Success;
    factoredDt_ = params.dt;
    factoredDamping_ = params.bendingDamping;
}

// Backward Euler for gravity and the bending force f = -Q x:
// (M + (h² + βh) Q) v' = M v + h M g - h Q x.
// Gravity belongs inside this solve, not in the sub-steps: applied in the sub-steps,
// the velocity left after the solve (−g h (n+1)/2n at rest) met the damping and h²
// terms, and a clamped strip sank by (h + β) g h (n+1)/2n, 0.32 mm whatever its D.
void XpbdIntegrator::bendImplicitly(Sheet& sheet, const SimParams& params, const Vec3& g) {
    auto& V = sheet.verts;
    const Index nv = V.size();
    if (!factored_ || nv == 0) {
        for (Index i = 0; i < nv; ++i)
            if (!V.pinned[i]) V.v[i] += params.dt * g;
        return;
    }
    rhs_.resize(nv, 3);
    sol_.resize(nv, 3);
    for (Index i = 0; i < nv; ++i) rhs_.row(i) = V.x[i].transpose();
    sol_ = bending_ * rhs_; // Q x
    const double h = params.dt;
    for (Index i = 0; i < nv; ++i)
        rhs_.row(i) = (solveMass_[i] * V.v[i] + h * V.m[i] * g).transpose() - h * sol_.row(i);
    sol_ = solver_.solve(rhs_);
    for (Index i = 0; i < nv; ++i)
        if (!V.pinned[i]) V.v[i] = sol_.row(i).transpose();
}

bool XpbdIntegrator::mustWake(const Sheet& sheet) const {
    const auto& V = sheet.verts;
    for (Index i = 0; i < V.size(); ++i)
        if (V.pinned[i] && V.v[i] != Vec3::Zero()) return true;
    const SphereTool& sp = contacts_.sphere;
    if (!sp.active || sp.velocity.squaredNorm() == 0.0) return false;
    const double reach = sp.radius + kToolReach + 0.01;
    for (Index i = 0; i < V.size(); ++i)
        if ((V.x[i] - sp.center).squaredNorm() < reach * reach) return true;
    return false;
}

bool XpbdIntegrator::shouldSleep(const Sheet& sheet) const {
    const auto& V = sheet.verts;
    constexpr double kQuietSpeed = 5e-4; // m/s
    for (Index i = 0; i < V.size(); ++i)
        if (!V.pinned[i] && V.v[i].squaredNorm() > kQuietSpeed * kQuietSpeed) return false;
    return !mustWake(sheet);
}

void XpbdIntegrator::advance(Sheet& sheet, const SimParams& params) {
    auto& V = sheet.verts;
    const auto& S = sheet.springs;
    const Index nv = V.size();
    std::int64_t active = 0;
    for (const DamageEvent& ev : sheet.events) active += ev.active ? 1 : 0;
    std::int64_t pins = 0, pinSum = 0;
    for (Index i = 0; i < nv; ++i)
        if (V.pinned[i]) {
            ++pins;
            pinSum += i;
        }
    const std::array<std::int64_t, 7> signature{nv,
                                                S.size(),
                                                sheet.triangleCount(),
                                                static_cast<std::int64_t>(sheet.events.size()),
                                                active,
                                                pins,
                                                pinSum};
    if (signature != signature_ || !(builtFor_ == params.material)) {
        rebuild(sheet, params);
        signature_ = signature;
        asleep_ = false;
        quietSteps_ = 0;
    } else if (params.dt != factoredDt_ || params.bendingDamping != factoredDamping_) {
        factor(sheet, params);
    }
    if (asleep_) {
        if (!mustWake(sheet)) {
            for (Index i = 0; i < nv; ++i)
                if (!V.pinned[i]) V.v[i] = Vec3::Zero();
            return;
        }
        asleep_ = false;
        quietSteps_ = 0;
    }

    const int n = std::max(1, params.substeps);
    const double h = params.dt / n;
    const double h2 = h * h;
    const Vec3 g =
        params.gravity * Vec3(std::sin(params.gravityTilt), -std::cos(params.gravityTilt), 0.0);
    const Material& mat = params.material;
    w_.resize(static_cast<std::size_t>(nv));
    for (Index i = 0; i < nv; ++i) w_[i] = V.pinned[i] || !(V.m[i] > 0.0) ? 0.0 : 1.0 / V.m[i];
    xPrev_.resize(static_cast<std::size_t>(nv));
    const SphereTool& sp = contacts_.sphere;
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
    const auto collideSphere = [&](const Vec3& c, const Vec3& cPrev, bool withFriction) {
        if (!sp.active) return;
        const double reach = sp.radius + kToolReach;
        for (Index i = 0; i < nv; ++i) {
            if (w_[i] == 0.0) continue;
            const Vec3 d = V.x[i] - c;
            const double dist2 = d.squaredNorm();
            if (!(dist2 < reach * reach)) continue;
            const double dist = std::sqrt(dist2);
            const Vec3 nrm = dist > 1e-12 ? Vec3(d / dist) : Vec3::UnitY();
            const double push = reach - dist;
            V.x[i] = c + reach * nrm;
            touched_[i] = 1;
            if (!withFriction) continue;
            const Vec3 rel = (V.x[i] - xPrev_[i]) - (c - cPrev);
            friction(V.x[i], rel - rel.dot(nrm) * nrm, push, mat.toolStaticFriction,
                     mat.toolKineticFriction);
        }
    };
    const auto collideGround = [&](bool withFriction) {
        if (!contacts_.ground) return;
        const double gh = contacts_.groundHeight;
        for (Index i = 0; i < nv; ++i) {
            if (w_[i] == 0.0 || !(V.x[i].y() < gh)) continue;
            const double push = gh - V.x[i].y();
            V.x[i].y() = gh;
            if (touched_[i] || !withFriction) continue;
            Vec3 slip = V.x[i] - xPrev_[i];
            slip.y() = 0.0;
            friction(V.x[i], slip, push, mat.groundStaticFriction, mat.groundKineticFriction);
        }
    };

    bendImplicitly(sheet, params, g);
    for (int sub = 0; sub < n; ++sub) {
        for (Index i = 0; i < nv; ++i) {
            xPrev_[i] = V.x[i];
            V.x[i] += h * V.v[i];
        }
        const Vec3 c = sphereStart + sp.velocity * (h * (sub + 1));
        const Vec3 cPrev = c - sp.velocity * h;
        // Contacts with friction first, on the predicted motion, so that the stretch
        // pass after them is not undone by friction (that left 7 % stretch in press);
        // then the desk and the tool once more without friction, the desk last, so
        // that nothing ends a sub-step inside either.
        std::fill(touched_.begin(), touched_.end(), std::uint8_t{0});
        collideSphere(c, cPrev, true);
        collideGround(true);
        // Forward then backward, so that a pull travels across the sheet both ways
        // within one sub-step.
        const double invH2 = 1.0 / h2;
        const std::size_t nc = stretch_.size();
        for (int pass = 0; pass < 2; ++pass)
            for (std::size_t q = 0; q < nc; ++q) {
                const StretchConstraint& k = stretch_[pass == 0 ? q : nc - 1 - q];
                const double wa = w_[k.a], wb = w_[k.b];
                const double wsum = wa + wb;
                if (wsum == 0.0) continue;
                const Vec3 d = V.x[k.a] - V.x[k.b];
                const double len = d.norm();
                if (!(len > 1e-12)) continue;
                const double dl =
                    std::min(-(len - k.rest) / (wsum + k.compliance * invH2), k.maxPush * h2);
                const Vec3 u = d * (dl / len);
                V.x[k.a] += wa * u;
                V.x[k.b] -= wb * u;
            }
        // Long-range attachments (Kim et al. 2012): no vertex gets farther from its
        // nearest pinned vertex than the paper between them allows, so a hanging sheet
        // holds its length without the pull walking one edge per pass from the pins.
        for (const Tether& t : tethers_) {
            const Vec3 d = V.x[t.vertex] - V.x[t.pin];
            const double len = d.norm();
            if (len > t.length) V.x[t.vertex] = V.x[t.pin] + d * (t.length / len);
        }
        collideSphere(c, cPrev, false);
        collideGround(false);
        collideSphere(c, cPrev, false);
        collideGround(false);
        for (Index i = 0; i < nv; ++i)
            if (w_[i] != 0.0) V.v[i] = (V.x[i] - xPrev_[i]) / h;
    }

    if (shouldSleep(sheet)) {
        if (++quietSteps_ >= kStepsBeforeSleep) {
            asleep_ = true;
            for (Index i = 0; i < nv; ++i)
                if (!V.pinned[i]) V.v[i] = Vec3::Zero();
        }
    } else {
        quietSteps_ = 0;
    }
}

} // namespace pf
