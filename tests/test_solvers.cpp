// The paper's Jacobi iteration (Eq. 6) against the exact solution of the same system.
#include "BackwardEulerIntegrator.h"
#include "ImplicitSystem.h"
#include "ProjectionSystem.h"
#include "Rng.h"
#include "SheetBuilder.h"
#include "StretchPass.h"
#include "SymmetricAmdOrdering.h"
#include "VectorLdlt.h"

#include <QTest>

using namespace pf;

namespace {

// The flat 9 × 12 sheet the tests below start from.
Sheet smallSheet() {
    SheetSpec spec;
    spec.columns = 9;
    spec.rows = 12;
    return buildRectangleSheet(spec);
}

// A sheet stretched by 4 % in-plane with random velocities: every spring is longer
// than its rest length, so every block is positive definite without any clamping.
Sheet stretchedSheet() {
    Sheet s = smallSheet();
    Rng rng(7);
    for (Index i = 0; i < s.verts.size(); ++i) {
        s.verts.x[i] *= 1.04;
        s.verts.v[i] = Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    }
    return s;
}

double norm(const std::vector<Vec3>& e, const std::vector<Vec3>& weighted) {
    double sum = 0.0;
    for (std::size_t i = 0; i < e.size(); ++i) sum += e[i].dot(weighted[i]);
    return std::sqrt(sum);
}

std::vector<Vec3> diff(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    std::vector<Vec3> d(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
    return d;
}

// The fast projection's matrix for the constraints `ends` at positions x, both ways:
// every free vertex's d × d block and the compliance summed by Eigen's setFromTriplets
// (whole), and assembleProjectionSystem (lower triangle).
struct ProjectionSystems {
    Eigen::SparseMatrix<double> full, lower;
};
ProjectionSystems projectionSystems(const std::vector<std::pair<Index, Index>>& ends,
                                    const std::vector<Vec3>& x, const std::vector<double>& w,
                                    double compliance) {
    const Index nv = static_cast<Index>(x.size()), n = static_cast<Index>(ends.size());
    std::vector<Vec3> dir(n);
    for (Index e = 0; e < n; ++e) dir[e] = (x[ends[e].first] - x[ends[e].second]).normalized();
    std::vector<Index> start(nv + 1, 0);
    for (const auto& [a, b] : ends) {
        ++start[a + 1];
        ++start[b + 1];
    }
    for (Index i = 0; i < nv; ++i) start[i + 1] += start[i];
    std::vector<ConstraintAtVertex> incident(start[nv]);
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index e = 0; e < n; ++e) {
        incident[fill[ends[e].first]++] = {e, 1.0};
        incident[fill[ends[e].second]++] = {e, -1.0};
    }
    std::vector<Eigen::Triplet<double>> entries;
    for (Index i = 0; i < nv; ++i) {
        if (w[i] == 0.0) continue;
        for (Index p = start[i]; p < start[i + 1]; ++p)
            for (Index r = start[i]; r < start[i + 1]; ++r) {
                const auto [e, se] = incident[p];
                const auto [f, sf] = incident[r];
                entries.emplace_back(e, f, w[i] * se * sf * dir[e].dot(dir[f]));
            }
    }
    for (Index e = 0; e < n; ++e)
        entries.emplace_back(e, e, compliance * (w[ends[e].first] + w[ends[e].second]));
    ProjectionSystems systems;
    systems.full.resize(n, n);
    systems.full.setFromTriplets(entries.begin(), entries.end());
    assembleProjectionSystem(ends, dir, w, start, incident, compliance, systems.lower);
    return systems;
}

} // namespace

class TestSolvers : public QObject {
    Q_OBJECT

  private slots:
    // The xpbd step's bending solve: one walk over the factor for x, y and z together
    // must give exactly what Eigen's column-by-column solve gives (the step's results,
    // and so every saved sheet and hash, stay as they were), on a matrix whose ordering
    // permutes the unknowns and whose factor fills in.
    void vectorLdltIsEigensSolveBitForBit() {
        const int side = 13, n = side * side;
        Rng rng(3);
        std::vector<Eigen::Triplet<double>> entries;
        for (int r = 0; r < side; ++r)
            for (int c = 0; c < side; ++c) {
                const int i = r * side + c;
                entries.emplace_back(i, i, 1.0 + rng.uniform()); // a mass
                // Second differences along both directions and across a diagonal, as a
                // plate's bending stencils couple a vertex with its neighbours' neighbours.
                const int neighbours[3][2] = {{0, 1}, {1, 0}, {1, 1}};
                for (const auto& d : neighbours) {
                    if (r + 2 * d[0] >= side || c + 2 * d[1] >= side) continue;
                    const int v[3] = {i, (r + d[0]) * side + c + d[1],
                                      (r + 2 * d[0]) * side + c + 2 * d[1]};
                    const double k[3] = {1.0, -2.0, 1.0};
                    const double weight = 50.0 * (0.5 + rng.uniform());
                    for (int a = 0; a < 3; ++a)
                        for (int b = 0; b < 3; ++b)
                            entries.emplace_back(v[a], v[b], weight * k[a] * k[b]);
                }
            }
        Eigen::SparseMatrix<double> a(n, n);
        a.setFromTriplets(entries.begin(), entries.end());
        std::vector<Vec3> b(n);
        Eigen::MatrixXd bColumns(n, 3);
        for (int i = 0; i < n; ++i) {
            b[i] = Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
            bColumns.row(i) = b[i].transpose();
        }
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> eigen(a);
        QCOMPARE(eigen.info(), Eigen::Success);
        VectorLdlt ours;
        QVERIFY(ours.compute(a));
        QVERIFY(eigen.matrixL().nestedExpression().nonZeros() > 4 * n); // it fills in
        int moved = 0; // and its ordering permutes the unknowns
        for (int i = 0; i < n; ++i) moved += eigen.permutationP().indices()[i] != i ? 1 : 0;
        QVERIFY(moved > 0);
        const Eigen::MatrixXd expected = eigen.solve(bColumns);
        std::vector<Vec3> x;
        ours.solve(b, x);
        QCOMPARE(static_cast<int>(x.size()), n);
        int differing = 0;
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) differing += x[i][c] != expected(i, c) ? 1 : 0;
        QCOMPARE(differing, 0);
        // And it solves the system.
        std::vector<Vec3> ax;
        multiplyEachCoordinate(a, x, ax);
        double residual = 0.0;
        for (int i = 0; i < n; ++i) residual = std::max(residual, (ax[i] - b[i]).norm());
        QVERIFY2(residual < 1e-12, qPrintable(QString::number(residual)));
        // The product, too, is Eigen's to the bit.
        const Eigen::MatrixXd product = a * bColumns;
        std::vector<Vec3> ab;
        multiplyEachCoordinate(a, b, ab);
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) differing += ab[i][c] != product(i, c) ? 1 : 0;
        QCOMPARE(differing, 0);
    }

    // The fast projection's matrix, written column by column, against every vertex's
    // d × d block summed by Eigen's setFromTriplets (how the projection assembled it
    // before, and what the saved sheets and pinned hashes were made with): the same lower
    // triangle to the bit, with pinned vertices, a constraint pinned at both ends and two
    // constraints between the same two vertices. And its LDLT, ordered without Eigen's
    // second Aᵀ + A, orders and solves it exactly as Eigen's default LDLT does.
    void projectionSystemIsTheTripletSumBitForBit() {
        const Sheet sheet = smallSheet();
        Rng rng(11);
        const Index nv = sheet.verts.size();
        std::vector<Vec3> x(nv);
        std::vector<double> w(nv);
        for (Index i = 0; i < nv; ++i) {
            x[i] = sheet.verts.x[i] +
                   0.003 * Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
            w[i] = rng.uniform() < 0.15 ? 0.0 : 1.0 / (1e-6 * (0.2 + rng.uniform()));
        }
        std::vector<std::pair<Index, Index>> ends;
        for (Index s = 0; s < sheet.springs.size(); ++s)
            if (sheet.springs.kind[s] == SpringKind::Structural && rng.uniform() < 0.8 &&
                w[sheet.springs.a[s]] + w[sheet.springs.b[s]] != 0.0)
                ends.emplace_back(sheet.springs.a[s], sheet.springs.b[s]);
        QVERIFY(ends.size() > 150);
        ends.emplace_back(ends[20].second, ends[20].first); // a second edge beside one
        const std::size_t pinnedEdge = ends.size();
        for (Index s = 0; s < sheet.springs.size(); ++s)
            if (sheet.springs.kind[s] == SpringKind::Structural &&
                w[sheet.springs.a[s]] + w[sheet.springs.b[s]] == 0.0) {
                ends.emplace_back(sheet.springs.a[s], sheet.springs.b[s]);
                break;
            }
        QCOMPARE(ends.size(), pinnedEdge + 1);
        const double compliance = 1e-3;
        const ProjectionSystems both = projectionSystems(ends, x, w, compliance);
        const Eigen::SparseMatrix<double> expected = both.full.triangularView<Eigen::Lower>();
        const Eigen::SparseMatrix<double>& lower = both.lower;
        QVERIFY(lower.isCompressed());
        QCOMPARE(lower.nonZeros(), expected.nonZeros());
        int differing = 0;
        for (Index f = 0; f < lower.cols(); ++f) {
            QCOMPARE(lower.outerIndexPtr()[f + 1], expected.outerIndexPtr()[f + 1]);
            for (Index k = lower.outerIndexPtr()[f]; k < lower.outerIndexPtr()[f + 1]; ++k) {
                differing += lower.innerIndexPtr()[k] != expected.innerIndexPtr()[k] ? 1 : 0;
                differing += lower.valuePtr()[k] != expected.valuePtr()[k] ? 1 : 0;
            }
        }
        QCOMPARE(differing, 0);
        // Both vertices of the doubled edge sum into the entry the two edges share, and
        // the edge pinned at both ends has only its (zero) compliance term.
        QVERIFY(lower.coeff(static_cast<Index>(pinnedEdge) - 1, 20) != 0.0);
        QCOMPARE(lower.col(static_cast<Index>(pinnedEdge)).nonZeros(), Eigen::Index(1));

        // The projection never holds an edge pinned at both ends (its pivot is zero).
        ends.pop_back();
        const ProjectionSystems held = projectionSystems(ends, x, w, compliance);
        const Index n = static_cast<Index>(ends.size());
        Eigen::VectorXd c(n);
        for (Index e = 0; e < n; ++e) c[e] = 1e-4 * (rng.uniform() - 0.5);
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> eigen(held.full);
        SymmetricLdlt ours(held.lower);
        QCOMPARE(eigen.info(), Eigen::Success);
        QCOMPARE(ours.info(), Eigen::Success);
        int moved = 0;
        for (Index e = 0; e < n; ++e) {
            differing += ours.permutationP().indices()[e] != eigen.permutationP().indices()[e];
            moved += eigen.permutationP().indices()[e] != e ? 1 : 0;
        }
        QCOMPARE(differing, 0);
        QVERIFY(moved > n / 2); // a real ordering, not the identity
        const Eigen::VectorXd expectedLambda = eigen.solve(c), lambda = ours.solve(c);
        for (Index e = 0; e < n; ++e) differing += lambda[e] != expectedLambda[e] ? 1 : 0;
        QCOMPARE(differing, 0);
        // And it solves the system.
        const double residual =
            (held.full.selfadjointView<Eigen::Lower>() * lambda - c).norm() / c.norm();
        QVERIFY2(residual < 1e-8, qPrintable(QString::number(residual)));
    }

    // The xpbd sub-steps' stretch pass takes each colour in blocks, with the square roots
    // and divisions of a block together: it must give exactly what taking the constraints
    // one at a time in the same order gives, forward and then backward, with constraints
    // held at their caps, a degenerate edge, and a group whose constraints share vertices.
    void stretchPassIsTheSequentialPassBitForBit() {
        const Sheet sheet = smallSheet();
        Rng rng(11);
        std::vector<Vec3> start = sheet.verts.x;
        for (Vec3& x : start)
            x += 0.004 * Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
        start[1] = start[0]; // edge 0-1 has no direction
        const auto& S = sheet.springs;
        std::vector<DistanceConstraint> all;
        for (Index s = 0; s < S.size(); ++s) {
            if (S.kind[s] != SpringKind::Structural) continue;
            const double cap = rng.uniform() < 0.3 ? 1e-5 : 1.0; // some held at their cap
            all.push_back({S.a[s], S.b[s], 1.0 + rng.uniform(), 1.0 + rng.uniform(), S.rest[s],
                           0.4 + 0.1 * rng.uniform(), -cap, 0.5 * cap});
        }
        // Greedy colours, as the integrator makes them, and a last group that shares.
        std::vector<std::uint64_t> used(static_cast<std::size_t>(sheet.verts.size()), 0);
        std::vector<std::pair<int, DistanceConstraint>> coloured;
        for (const DistanceConstraint& k : all) {
            int c = 0;
            while (c < 62 && ((used[k.a] | used[k.b]) & (std::uint64_t{1} << c))) ++c;
            used[k.a] |= std::uint64_t{1} << c;
            used[k.b] |= std::uint64_t{1} << c;
            coloured.push_back({c, k});
        }
        std::stable_sort(coloured.begin(), coloured.end(),
                         [](const auto& x, const auto& y) { return x.first < y.first; });
        for (std::size_t q = 0; q < 20; ++q) coloured.push_back({63, all[q]});
        StretchPass pass;
        std::vector<DistanceConstraint> order;
        for (const auto& [colour, k] : coloured) {
            pass.add(k, colour, colour == 63);
            order.push_back(k);
        }
        QCOMPARE(pass.size(), order.size());
        const auto relaxOne = [](const DistanceConstraint& k, std::vector<Vec3>& x) {
            const Vec3 d = x[k.a] - x[k.b];
            const double len = d.norm();
            if (!(len > 1e-12)) return;
            const double dl = std::clamp((k.rest - len) * k.gain, k.lowest, k.highest);
            const Vec3 u = d * (dl / len);
            x[k.a] += k.wa * u;
            x[k.b] -= k.wb * u;
        };
        std::vector<Vec3> expected = start, ours = start;
        for (int sweep = 0; sweep < 3; ++sweep) {
            for (const DistanceConstraint& k : order) relaxOne(k, expected);
            for (auto k = order.rbegin(); k != order.rend(); ++k) relaxOne(*k, expected);
            pass.relax(ours);
        }
        int differing = 0, moved = 0;
        for (std::size_t i = 0; i < start.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                differing += ours[i][c] != expected[i][c] ? 1 : 0;
                moved += ours[i][c] != start[i][c] ? 1 : 0;
            }
        QCOMPARE(differing, 0);
        QVERIFY(moved > static_cast<int>(start.size())); // the passes did move the sheet
    }

    void conjugateGradientSolvesTheSystem() {
        const Sheet s = stretchedSheet();
        SimParams p;
        ImplicitSystem sys;
        sys.assemble(s, p, false);
        std::vector<Vec3> dv, Adv;
        QVERIFY(BackwardEulerIntegrator::solveExact(s, sys, dv));
        sys.multiply(s, dv, Adv);
        double res = 0, rhs = 0;
        for (Index i = 0; i < s.verts.size(); ++i) {
            res += (Adv[i] - sys.rhs[i]).squaredNorm();
            rhs += sys.rhs[i].squaredNorm();
        }
        QVERIFY2(std::sqrt(res / rhs) < 1e-10, qPrintable(QString::number(std::sqrt(res / rhs))));
    }

    void jacobiApproachesExactSolutionMonotonically_data() {
        QTest::addColumn<double>("dt");
        QTest::addColumn<bool>("scalar");
        QTest::newRow("3x3 blocks, h=1/240") << 1.0 / 240 << false;
        QTest::newRow("3x3 blocks, h=1/60") << 1.0 / 60 << false;
        QTest::newRow("scalar blocks, h=1/240") << 1.0 / 240 << true;
    }
    void jacobiApproachesExactSolutionMonotonically() {
        QFETCH(double, dt);
        QFETCH(bool, scalar);
        const Sheet s = stretchedSheet();
        SimParams p;
        p.dt = dt;
        ImplicitSystem sys;
        sys.assemble(s, p, scalar);
        std::vector<Vec3> exact, dv, scratch, Ae, Me, Aexact;
        QVERIFY(BackwardEulerIntegrator::solveExact(s, sys, exact));
        sys.multiply(s, exact, Aexact);
        const double exactA = norm(exact, Aexact);

        // Errors in the energy norm ‖e‖_A (in which a convergent Jacobi iteration on a
        // symmetric positive definite system contracts every sweep) and in the mass norm.
        double lastA = std::numeric_limits<double>::infinity();
        double lastM = lastA, firstA = 0;
        QStringList trace;
        for (int k = 0; k <= 8; ++k) {
            solveJacobi(s, sys, k, dv, scratch);
            const auto e = diff(dv, exact);
            sys.multiply(s, e, Ae);
            Me.resize(e.size());
            for (std::size_t i = 0; i < e.size(); ++i) Me[i] = s.verts.m[i] * e[i];
            const double errA = norm(e, Ae) / exactA;
            const double errM = norm(e, Me);
            trace << QString::number(errM, 'g', 3);
            QVERIFY2(errA < lastA, qPrintable(QStringLiteral("A-norm grew at k=%1").arg(k)));
            QVERIFY2(errM < lastM, qPrintable(QStringLiteral("M-norm grew at k=%1: %2")
                                                  .arg(k)
                                                  .arg(trace.join(QLatin1Char(' ')))));
            if (k == 0) firstA = errA;
            lastA = errA;
            lastM = errM;
        }
        QVERIFY(lastA < 0.8 * firstA);
    }
};

QTEST_APPLESS_MAIN(TestSolvers)
#include "test_solvers.moc"
