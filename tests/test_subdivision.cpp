// Paper §4.3: Hermite midpoints, σ, and a crack-free subdivided surface.
#include "JacobiScene.h"
#include "Normals.h"
#include "Rng.h"
#include "Scenes.h"
#include "SheetValidation.h"
#include "Simulation.h"
#include "Subdivision.h"

#include <QTest>
#include <map>

using namespace pf;

class TestSubdivision : public QObject {
    Q_OBJECT

  private slots:
    void theInteractiveBudgetPicksTheFinestLevelThatFits() {
        // A fresh A4 sheet (900 triangles) fits level 3 in 65,536 triangles (57,600).
        QCOMPARE(subdivisionWithin(3, 900, 65536), 3);
        QCOMPARE(subdivisionWithin(3, 1024, 65536), 3); // exactly 65,536
        QCOMPARE(subdivisionWithin(3, 1025, 65536), 2);
        QCOMPARE(subdivisionWithin(3, 16384, 65536), 1);
        QCOMPARE(subdivisionWithin(3, 20000, 65536), 0); // level 0 is always allowed
        QCOMPARE(subdivisionWithin(1, 10, 65536), 1);    // never finer than asked
        QCOMPARE(subdivisionWithin(0, 10, 65536), 0);
    }

    void sigmaZeroGivesThePlainMidpoint() {
        const Vec3 a(0.1, 0.2, 0.3), b(0.7, -0.1, 0.4);
        const Vec3 na = Vec3(0.2, 1, 0).normalized(), nb = Vec3(-0.3, 1, 0.1).normalized();
        QCOMPARE(hermiteMidpoint(a, b, na, nb, 0.0), Vec3(0.5 * (a + b)));
    }

    void midpointByHand() {
        // x_i = 0, x_j = (1, 0, 0), n_i = (-s, c, 0), n_j = (s, c, 0) (a ridge), σ = 1:
        // C'(0) = v - (v·n_i) n_i = (1,0,0) + s(-s, c, 0) = (c², sc, 0),
        // C'(1) = (1,0,0) - s(s, c, 0) = (c², -sc, 0), m = (0.5, 0, 0) + (0, 2sc, 0)/8.
        const double s = 0.6, c = 0.8;
        const Vec3 m =
            hermiteMidpoint(Vec3::Zero(), Vec3::UnitX(), Vec3(-s, c, 0), Vec3(s, c, 0), 1.0);
        QVERIFY((m - Vec3(0.5, 2 * s * c / 8, 0)).norm() < 1e-15);
    }

    void midpointIsSymmetricToTheLastBit() {
        Rng rng(3);
        for (int k = 0; k < 1000; ++k) {
            auto r = [&] {
                return Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
            };
            const Vec3 a = r(), b = r(), na = r().normalized(), nb = r().normalized();
            const double sigma = 2 * rng.uniform();
            const Vec3 ab = hermiteMidpoint(a, b, na, nb, sigma);
            const Vec3 ba = hermiteMidpoint(b, a, nb, na, sigma);
            QVERIFY(ab == ba); // bitwise: neighbouring triangles share the point exactly
            QVERIFY(midpointNormal(na, nb) == midpointNormal(nb, na));
        }
    }

    void sharedMidpointsCoincideAcrossTriangles() {
        // Evaluate every edge's midpoint from each of its two triangles, in that
        // triangle's own vertex order, and compare: the paper's per-triangle recursion
        // would then produce no cracks.
        Simulation sim(test::jacobiScene("press"));
        for (int k = 0; k < 300; ++k) sim.step();
        const Sheet& s = sim.world().sheet;
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        std::map<std::pair<Index, Index>, Vec3> seen;
        int shared = 0;
        for (const Triangle& t : s.tris)
            for (int k = 0; k < 3; ++k) {
                const Index a = t.v[k], b = t.v[(k + 1) % 3];
                const Vec3 m = hermiteMidpoint(s.verts.x[a], s.verts.x[b], n[a], n[b], 1.0);
                auto [it, fresh] = seen.try_emplace(std::minmax(a, b), m);
                if (!fresh) {
                    QVERIFY(it->second == m);
                    ++shared;
                }
            }
        QVERIFY(shared > 1000);
    }

    void subdividedSurfaceIsAClosedUpDisc_data() {
        QTest::addColumn<int>("level");
        for (int l = 0; l <= kMaxSubdivisionLevel; ++l) QTest::addRow("level %d", l) << l;
    }
    void subdividedSurfaceIsAClosedUpDisc() {
        QFETCH(int, level);
        Simulation sim(test::jacobiScene("press"));
        for (int k = 0; k < 200; ++k) sim.step();
        const Sheet& s = sim.world().sheet;
        const SurfaceMesh m = subdivideSheet(s, 1.0, level);
        const std::size_t F0 = s.tris.size();
        QCOMPARE(m.triangles.size(), F0 << (2 * level));
        // Edge use: every edge in one or two triangles; V - E + F = 1 (a disc, no cracks).
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
        for (const auto& t : m.triangles)
            for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
        for (const auto& [e, count] : uses) QVERIFY(count == 1 || count == 2);
        const long chi = static_cast<long>(m.positions.size()) - static_cast<long>(uses.size()) +
                         static_cast<long>(m.triangles.size());
        QCOMPARE(chi, 1L);
        for (const Vec3& p : m.positions) QVERIFY(p.allFinite());
        for (const Vec3& nn : m.normals) QVERIFY(std::abs(nn.norm() - 1.0) < 1e-12);
    }

    // Texture coordinates are the material coordinates over the sheet: at a sheet vertex,
    // its (X + w/2, Z + l/2) / (w, l) on the A4 rectangle; and since each midpoint takes
    // the material midpoint's, the subdivided triangles tile the unit square in uv
    // exactly once, none flipped, also across the vertices that breaks inserted.
    void textureCoordinatesAreTheMaterialCoordinates() {
        Simulation sim(test::jacobiScene("press"));
        for (int k = 0; k < 200; ++k) sim.step();
        const Sheet& s = sim.world().sheet;
        QVERIFY(!s.events.empty()); // broken: inserted vertices on the way
        const double w = 0.210, l = 0.297;
        for (int level = 0; level <= 3; ++level) {
            const SurfaceMesh m = subdivideSheet(s, 1.0, level);
            QCOMPARE(m.uvs.size(), m.positions.size());
            for (Index i = 0; i < s.verts.size(); ++i) {
                const Vec2 want((s.verts.X[i].x() + w / 2) / w, (s.verts.X[i].y() + l / 2) / l);
                QVERIFY2((m.uvs[i] - want).norm() < 1e-12, qPrintable(QString::number(i)));
            }
            double area = 0.0;
            int flipped = 0;
            for (const auto& t : m.triangles) {
                const Vec2 a = m.uvs[t[1]] - m.uvs[t[0]], b = m.uvs[t[2]] - m.uvs[t[0]];
                const double signedArea = 0.5 * (a.x() * b.y() - a.y() * b.x());
                area += std::abs(signedArea);
                flipped += signedArea > 0 ? 1 : 0;
            }
            // One orientation for all (which one is the mesh's winding).
            QVERIFY2(flipped == 0 || flipped == int(m.triangles.size()),
                     qPrintable(QStringLiteral("%1 of %2").arg(flipped).arg(m.triangles.size())));
            QVERIFY2(std::abs(area - 1.0) < 1e-9, qPrintable(QString::number(area, 'g', 15)));
        }
    }

    void sigmaChangesTheSurface() {
        Simulation sim(test::jacobiScene("press"));
        for (int k = 0; k < 300; ++k) sim.step();
        const SurfaceMesh flat = subdivideSheet(sim.world().sheet, 0.0, 2);
        const SurfaceMesh round = subdivideSheet(sim.world().sheet, 1.0, 2);
        double moved = 0;
        for (std::size_t i = 0; i < flat.positions.size(); ++i)
            moved = std::max(moved, (flat.positions[i] - round.positions[i]).norm());
        QVERIFY(moved > 1e-4); // metres
        // The original vertices never move.
        for (Index i = 0; i < sim.world().sheet.verts.size(); ++i)
            QCOMPARE(flat.positions[i], round.positions[i]);
    }
};

QTEST_APPLESS_MAIN(TestSubdivision)
#include "test_subdivision.moc"
