// The material model of the default integrator: constants derived from E·t and D, the
// same at two resolutions, and the bending stencils calibrated on a cylinder; plus the
// fidelity scorecard, whose every row is a bound from physics the project did not write.
#include "Fidelity.h"
#include "Material.h"
#include "SheetBuilder.h"
#include "XpbdIntegrator.h"

#include <QTest>
#include <algorithm>
#include <cmath>
#include <numbers>

using namespace pf;

namespace {

Sheet strip(double width, double length, double cell) {
    SheetSpec spec;
    spec.width = width;
    spec.length = length;
    spec.columns = static_cast<int>(std::lround(width / cell)) + 1;
    spec.rows = static_cast<int>(std::lround(length / cell)) + 1;
    return buildRectangleSheet(spec);
}

// Bending energy the stencils store for the sheet as it is now.
double stencilEnergy(const Sheet& sheet, const Material& m) {
    double e = 0.0;
    for (const auto& st : XpbdIntegrator::bendingStencils(sheet, m)) {
        Vec3 c = Vec3::Zero();
        for (int q = 0; q < st.count; ++q) c += st.k[q] * sheet.verts.x[st.v[q]];
        e += 0.5 * c.squaredNorm() / st.compliance;
    }
    return e;
}

// Rolls the flat sheet onto a cylinder of radius r whose axis runs along x (alongX) or
// along z; an isometry, so only bending stores energy.
void rollOnCylinder(Sheet& sheet, double r, bool alongX) {
    for (Index i = 0; i < sheet.verts.size(); ++i) {
        const Vec2 X = sheet.verts.X[i];
        const double s = alongX ? X.y() : X.x();
        const double a = s / r;
        const Vec3 p = alongX ? Vec3(X.x(), r - r * std::cos(a), r * std::sin(a))
                              : Vec3(r * std::sin(a), r - r * std::cos(a), X.y());
        sheet.verts.x[i] = p;
    }
}

} // namespace

class TestMaterial : public QObject {
    Q_OBJECT
  private slots:
    void presetsAreOrderedByStiffness() {
        Material tissue, office, card;
        QVERIFY(materialPreset("tissue", tissue));
        QVERIFY(materialPreset("office", office));
        QVERIFY(materialPreset("card", card));
        QVERIFY(!materialPreset("rubber", office));
        QVERIFY(tissue.bendingStiffness < office.bendingStiffness);
        QVERIFY(office.bendingStiffness < card.bendingStiffness);
        QVERIFY(tissue.arealDensity < office.arealDensity);
        QVERIFY(office.arealDensity < card.arealDensity);
    }

    // A sheet pulled uniformly by strain ε along x stores ½ E·t ε² per area (ν = 1/3
    // only enters across; the springs are checked against the uniaxial-stress
    // modulus) at any resolution: the constants are per element, not per spring.
    void stretchStiffnessIsResolutionIndependent_data() {
        QTest::addColumn<double>("cell");
        QTest::newRow("11.7 mm") << 0.0117;
        QTest::newRow("5 mm") << 0.005;
    }
    void stretchStiffnessIsResolutionIndependent() {
        QFETCH(double, cell);
        const Material m;
        const Sheet sheet = strip(0.2, 0.3, cell);
        const std::vector<double> k = XpbdIntegrator::stretchStiffness(sheet, m);
        // Equal biaxial strain ε: every spring stretches by ε l0; the continuum stores
        // E·t ε² / (1 − ν) per area (ν = 1/3).
        const double eps = 1e-3;
        double e = 0.0;
        for (Index s = 0; s < sheet.springs.size(); ++s)
            if (sheet.springs.kind[s] == SpringKind::Structural)
                e += 0.5 * k[s] * std::pow(eps * sheet.springs.rest[s], 2);
        const double area = 0.2 * 0.3;
        const double expected = m.stretchStiffness * eps * eps / (1.0 - 1.0 / 3.0) * area;
        QVERIFY2(std::abs(e / expected - 1.0) < 0.02,
                 qPrintable(QStringLiteral("energy %1 vs %2").arg(e).arg(expected)));
    }

    // Rolled onto a cylinder of radius r, the sheet must store ½ D / r² per area, in
    // either direction and at either resolution.
    void bendingMatchesCylinder_data() {
        QTest::addColumn<double>("cell");
        QTest::addColumn<bool>("alongX");
        QTest::newRow("11.7 mm, axis x") << 0.0117 << true;
        QTest::newRow("11.7 mm, axis z") << 0.0117 << false;
        QTest::newRow("5 mm, axis x") << 0.005 << true;
        QTest::newRow("5 mm, axis z") << 0.005 << false;
        QTest::newRow("strip 2.5 cm, 5 mm, axis x") << -0.005 << true;
    }
    void bendingMatchesCylinder() {
        QFETCH(double, cell);
        QFETCH(bool, alongX);
        const Material m;
        const double width = cell < 0 ? 0.025 : 0.2;
        Sheet sheet = strip(width, 0.3, std::abs(cell));
        const double r = 0.5;
        rollOnCylinder(sheet, r, alongX);
        const double e = stencilEnergy(sheet, m);
        const double expected = 0.5 * m.bendingStiffness / (r * r) * width * 0.3;
        QVERIFY2(std::abs(e / expected - 1.0) < 0.10,
                 qPrintable(QStringLiteral("energy %1 vs %2 (ratio %3)")
                                .arg(e)
                                .arg(expected)
                                .arg(e / expected)));
    }

    // Paper yields where its surface fibres do, at the curvature κ_y of a bend, however
    // the mesh's stencils measure it. Paper bends cylindrically (it is developable), so
    // each stencil's unit must make it read the curvature of a cylindrical bend in the
    // direction it reads most: then every stencil across a fold yields at the same
    // curvature. Read for a bowl, the plate's sum stencils (the two second differences
    // added) read half a fold's curvature and the mixed ones half a diagonal fold's;
    // they stayed elastic across a fold and pulled it back toward flat.
    void everyStencilReadsAFoldsCurvature() {
        const Material m;
        Sheet sheet = strip(0.2, 0.3, 0.0117);
        const Sheet flat = sheet;
        const double r = 0.05;
        const auto stencils = XpbdIntegrator::bendingStencils(sheet, m);
        std::vector<double> most(stencils.size(), 0.0);
        constexpr int kDirections = 24;
        for (int d = 0; d < kDirections; ++d) {
            // Rolled onto a cylinder whose axis lies along the material direction a.
            const double a = std::numbers::pi * d / kDirections;
            const Vec2 axis(std::cos(a), std::sin(a)), across(-std::sin(a), std::cos(a));
            for (Index i = 0; i < sheet.verts.size(); ++i) {
                const Vec2 X = flat.verts.X[i];
                const double s = X.dot(across), t = X.dot(axis);
                const double u = t * axis.x() + r * std::sin(s / r) * across.x();
                const double w = t * axis.y() + r * std::sin(s / r) * across.y();
                sheet.verts.x[i] = Vec3(u, r - r * std::cos(s / r), w);
            }
            for (std::size_t q = 0; q < stencils.size(); ++q) {
                Vec3 y = Vec3::Zero();
                for (int k = 0; k < stencils[q].count; ++k)
                    y += stencils[q].k[k] * sheet.verts.x[stencils[q].v[k]];
                most[q] = std::max(most[q], y.norm() / stencils[q].unit);
            }
        }
        const auto [low, high] = std::minmax_element(most.begin(), most.end());
        qInfo("over %zu stencils and %d fold directions, the most each reads: %.3f to %.3f of "
              "the fold's curvature",
              stencils.size(), kDirections, *low * r, *high * r);
        QCOMPARE_GE(*low * r, 0.97);
        QCOMPARE_LE(*high * r, 1.03);
    }

    void peirceFormula() {
        // l/c = (8 tan θ / cos(θ/2))^(1/3), inverted: check the round trip.
        for (double theta : {0.01, 0.2, 0.6, 1.2}) {
            const double ratio = std::cbrt(8.0 * std::tan(theta) / std::cos(theta / 2));
            QCOMPARE_LE(std::abs(peirceAngle(ratio * 0.07, 0.07) - theta), 1e-9);
        }
    }
};

QTEST_APPLESS_MAIN(TestMaterial)
#include "test_material.moc"
