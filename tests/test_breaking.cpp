// Eq. 10 and Eq. 11 against hand-computed values on a constructed configuration.
#include "Breaking.h"
#include "Normals.h"
#include "SheetValidation.h"
#include "TestSheets.h"

#include <QtTest>

using namespace pf;

class TestBreaking : public QObject {
    Q_OBJECT

  private slots:
    void normalsOfTheFoldedQuad() {
        const Sheet s = test::makeFoldedQuad();
        QCOMPARE(validateSheet(s), std::string());
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        QVERIFY((n[0] - Vec3(0, 1, 0)).norm() < 1e-15);
        QVERIFY((n[1] - Vec3(0, 1, 0)).norm() < 1e-15);
        QVERIFY((n[2] - Vec3(0, 0.8, -0.6)).norm() < 1e-15);
        QVERIFY((n[3] - Vec3(0, 0.8, 0.6)).norm() < 1e-15);
    }

    void probabilityOfEq10ByHand() {
        // l = 0.8, l0 = 1, l_rl = 0.8, n_ij = 1, n_rl = 0.64 - 0.36 = 0.28, φ = 0.5:
        // P = (1 - 0.8) · 0.8/1.6 · (1 - 0.5)(1 + 0.14)/4 = 0.2 · 0.5 · 0.1425 = 0.01425
        const Sheet s = test::makeFoldedQuad();
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        const auto& x = s.verts.x;
        const double P =
            breakProbability((x[0] - x[1]).norm(), s.springs.rest[0], (x[2] - x[3]).norm(),
                             n[0].dot(n[1]), n[2].dot(n[3]), 0.5);
        QVERIFY(std::abs(P - 0.01425) < 1e-15);
        // φ = 0 ignores curvature: 0.2 · 0.5 · 1/4.
        QVERIFY(std::abs(breakProbability(0.8, 1.0, 0.8, 1.0, 0.28, 0.0) - 0.025) < 1e-15);
        // A flat sheet at φ = 1 never breaks (the paper's remark under Eq. 9).
        QCOMPARE(breakProbability(0.8, 1.0, 0.8, 1.0, 1.0, 1.0), 0.0);
        // A stretched spring never breaks.
        QCOMPARE(breakProbability(1.1, 1.0, 0.8, 0.0, 0.0, 0.5), 0.0);
    }

    void probabilityPerStepComposes() {
        // Two steps of h must break as often as one step of 2h: 1-(1-p_h)^2 = p_2h.
        const double P = 0.3, ref = 1.0 / 60.0;
        const double ph = breakProbabilityPerStep(P, ref / 2, ref);
        QVERIFY(std::abs((1 - (1 - ph) * (1 - ph)) - P) < 1e-15);
        QCOMPARE(breakProbabilityPerStep(P, ref, ref), P);
        QCOMPARE(breakProbabilityPerStep(0.0, ref, ref), 0.0);
    }

    void offsetOfEq11ByHand() {
        // h = ψ/2 · sqrt(1 - 0.64) = ψ · 0.3
        QVERIFY(std::abs(breakOffset(0.8, 1.0, 0.5) - 0.15) < 1e-15);
        QVERIFY(std::abs(breakOffset(0.8, 1.0, 1.0) - 0.3) < 1e-15);
        QCOMPARE(breakOffset(0.8, 1.0, 0.0), 0.0);
        QCOMPARE(breakOffset(1.2, 1.0, 1.0), 0.0); // only for compressed springs
    }

    void breakPlacesNewVertexByEq11_data() {
        QTest::addColumn<double>("psi");
        QTest::newRow("psi=1") << 1.0;
        QTest::newRow("psi=0.5") << 0.5;
        QTest::newRow("psi=0") << 0.0;
    }
    void breakPlacesNewVertexByEq11() {
        QFETCH(double, psi);
        Sheet s = test::makeFoldedQuad();
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        const Index ev = breakEdge(s, 0, n, psi, 0);
        QCOMPARE(validateSheet(s), std::string());
        const DamageEvent& e = s.events[ev];
        const Vec3& xn = s.verts.x[e.vertex];
        // The edge is a valley (r, l above it): n moves down along n_e = (0, 1, 0).
        QVERIFY((xn - Vec3(0, -0.3 * psi, 0)).norm() < 1e-15);
        QVERIFY((s.verts.X[e.vertex] - Vec2(0, 0)).norm() < 1e-15);
        const double lin = (s.verts.x[0] - xn).norm();
        const double lnj = (xn - s.verts.x[1]).norm();
        QCOMPARE(s.springs.rest[e.springs[0]], 0.5); // l0/2 from material coordinates
        QCOMPARE(s.springs.rest[e.springs[1]], 0.5);
        if (psi == 1.0) {
            QVERIFY(std::abs(lin - 0.5) < 1e-9);
            QVERIFY(std::abs(lnj - 0.5) < 1e-9);
        } else {
            QVERIFY(lin < 0.5 - 1e-3); // smaller ψ leaves the halves compressed
        }
        // e_ij is now an unbreakable crease remembering the compressed length.
        QCOMPARE(s.springs.kind[0], SpringKind::Crease);
        QCOMPARE(s.springs.breakable[0], std::uint8_t(0));
        QVERIFY(std::abs(s.springs.rest[0] - 0.8) < 1e-15);
        // e_rn and e_nl are unbreakable, e_in and e_nj breakable.
        QCOMPARE(s.springs.breakable[e.springs[0]], std::uint8_t(1));
        QCOMPARE(s.springs.breakable[e.springs[1]], std::uint8_t(1));
        QCOMPARE(s.springs.breakable[e.springs[2]], std::uint8_t(0));
        QCOMPARE(s.springs.breakable[e.springs[3]], std::uint8_t(0));
        QCOMPARE(s.triangleCount(), 4);
    }

    void ridgeMovesTheOtherWay() {
        Sheet s = test::makeFoldedQuad();
        s.verts.x[2].y() = s.verts.x[3].y() = -0.3; // r, l below the edge: a ridge
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        const Index ev = breakEdge(s, 0, n, 1.0, 0);
        QVERIFY(s.verts.x[s.events[ev].vertex].y() > 0.29);
    }
};

QTEST_APPLESS_MAIN(TestBreaking)
#include "test_breaking.moc"
