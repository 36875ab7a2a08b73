// The paper's Jacobi iteration (Eq. 6) against the exact solution of the same system.
#include "BackwardEulerIntegrator.h"
#include "ImplicitSystem.h"
#include "Rng.h"
#include "SheetBuilder.h"

#include <QtTest>

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
