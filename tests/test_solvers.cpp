// The paper's Jacobi iteration (Eq. 6) against the exact solution of the same system.
#include "BackwardEulerIntegrator.h"
#include "ImplicitSystem.h"
#include "Rng.h"
#include "SheetBuilder.h"
#include "StretchPass.h"
#include "VectorLdlt.h"

#include <QTest>

using namespace pf;

namespace {

// A sheet stretched by 4 % in-plane with random velocities: every spring is longer
// than its rest length, so every block is positive definite without any clamping.
Sheet stretchedSheet() {
    SheetSpec spec;
    spec.columns = 9;
    spec.rows = 12;
    Sheet s = buildRectangleSheet(spec);
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

    // The xpbd sub-steps' stretch pass takes each colour in blocks, with the square roots
    // and divisions of a block together: it must give exactly what taking the constraints
    // one at a time in the same order gives, forward and then backward, with constraints
    // held at their caps, a degenerate edge, and a group whose constraints share vertices.
    void stretchPassIsTheSequentialPassBitForBit() {
        SheetSpec spec;
        spec.columns = 9;
        spec.rows = 12;
        const Sheet sheet = buildRectangleSheet(spec);
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
