// The spring force's Jacobian blocks against central finite differences.
#include "SpringForce.h"

#include <QTest>

using namespace pf;

class TestSpringForce : public QObject {
    Q_OBJECT

  private:
    // Relative Frobenius error of an analytic block against central differences of
    // the force on a with respect to x_b (wrt = 0) or v_b (wrt = 1).
    static double jacobianError(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb,
                                double rest, double k, double c, bool clamp, int wrt) {
        const SpringEval e = evaluateSpring(xa, xb, va, vb, rest, k, c, clamp);
        const double eps = 1e-6;
        Mat3 fd;
        for (int col = 0; col < 3; ++col) {
            Vec3 d = Vec3::Zero();
            d[col] = eps;
            const Vec3 fp = wrt == 0 ? evaluateSpring(xa, xb + d, va, vb, rest, k, c, clamp).force
                                     : evaluateSpring(xa, xb, va, vb + d, rest, k, c, clamp).force;
            const Vec3 fm = wrt == 0 ? evaluateSpring(xa, xb - d, va, vb, rest, k, c, clamp).force
                                     : evaluateSpring(xa, xb, va, vb - d, rest, k, c, clamp).force;
            fd.col(col) = (fp - fm) / (2 * eps);
        }
        const Mat3& analytic = wrt == 0 ? e.K : e.C;
        return (analytic - fd).norm() / fd.norm();
    }

  private slots:
    void stiffnessBlockMatchesFiniteDifferences_data() {
        QTest::addColumn<double>("rest");
        QTest::addColumn<bool>("clamp");
        QTest::newRow("stretched") << 0.8 << false;
        QTest::newRow("stretched, clamp has no effect") << 0.8 << true;
        QTest::newRow("compressed, exact Jacobian") << 1.6 << false;
    }
    void stiffnessBlockMatchesFiniteDifferences() {
        QFETCH(double, rest);
        QFETCH(bool, clamp);
        const Vec3 xa(0.1, -0.2, 0.3), xb(0.9, 0.4, -0.5); // |xb - xa| ≈ 1.28
        const Vec3 va(0.3, 0.1, -0.2), vb(-0.1, 0.5, 0.4);
        // Damping off: the force's x-dependence through damping is deliberately not in K.
        const double err = jacobianError(xa, xb, va, vb, rest, 250.0, 0.0, clamp, 0);
        QVERIFY2(err < 1e-5, qPrintable(QString::number(err)));
    }

    void dampingBlockMatchesFiniteDifferences() {
        const Vec3 xa(0.1, -0.2, 0.3), xb(0.9, 0.4, -0.5);
        const Vec3 va(0.3, 0.1, -0.2), vb(-0.1, 0.5, 0.4);
        const double err = jacobianError(xa, xb, va, vb, 1.0, 250.0, 0.7, false, 1);
        QVERIFY2(err < 1e-5, qPrintable(QString::number(err)));
    }

    void clampRemovesNegativeTransverseStiffness() {
        // Compressed spring: the exact K has eigenvalue k(1 - L/l) < 0 twice; clamped, it is 0.
        const Vec3 xa(0, 0, 0), xb(0.5, 0, 0);
        const double k = 100.0, rest = 1.0;
        const SpringEval exact =
            evaluateSpring(xa, xb, Vec3::Zero(), Vec3::Zero(), rest, k, 0, false);
        const SpringEval clamped =
            evaluateSpring(xa, xb, Vec3::Zero(), Vec3::Zero(), rest, k, 0, true);
        QCOMPARE(exact.K(1, 1), k * (1.0 - rest / 0.5)); // -100
        QCOMPARE(clamped.K(1, 1), 0.0);
        QCOMPARE(clamped.K(0, 0), k);
        // Force: k (l - L) along u on a: compressed, it pushes a away from b (-x).
        QCOMPARE(exact.force.x(), k * (0.5 - rest));
    }

    void coincidentEndsGiveNoForceAndNoNaN() {
        const SpringEval e = evaluateSpring(Vec3::Ones(), Vec3::Ones(), Vec3::Zero(), Vec3::UnitX(),
                                            1.0, 100.0, 1.0, true);
        QVERIFY(e.force.allFinite() && e.K.allFinite() && e.C.allFinite());
        QCOMPARE(e.force.norm(), 0.0);
    }
};

QTEST_APPLESS_MAIN(TestSpringForce)
#include "test_spring_force.moc"
