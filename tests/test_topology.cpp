// Mesh invariants under breaking, and recovery as the exact inverse of a break.
#include "Breaking.h"
#include "FoldPlan.h"
#include "Hinges.h"
#include "Normals.h"
#include "Rng.h"
#include "Scenes.h"
#include "SheetStats.h"
#include "SheetValidation.h"
#include "TestSheets.h"

#include <QTest>

using namespace pf;

namespace {

// Everything but the log, compared exactly (bitwise for doubles).
bool sameSheet(const Sheet& a, const Sheet& b, QString* why) {
    auto fail = [&](const char* what) {
        *why = QString::fromLatin1(what);
        return false;
    };
    if (a.verts.x != b.verts.x) return fail("positions");
    if (a.verts.v != b.verts.v) return fail("velocities");
    if (a.verts.m != b.verts.m) return fail("masses");
    if (a.verts.X != b.verts.X) return fail("material coordinates");
    if (a.verts.pinned != b.verts.pinned) return fail("pinned flags");
    if (a.springs.a != b.springs.a || a.springs.b != b.springs.b) return fail("spring ends");
    if (a.springs.rest != b.springs.rest) return fail("rest lengths");
    if (a.springs.kind != b.springs.kind) return fail("spring kinds");
    if (a.springs.breakable != b.springs.breakable) return fail("breakable flags");
    if (a.springs.hinged != b.springs.hinged) return fail("hinged flags");
    if (a.springs.faces != b.springs.faces) return fail("edge faces");
    if (a.springs.event != b.springs.event) return fail("event links");
    if (a.tris != b.tris) return fail("triangles");
    return true;
}

// Breakable structural springs with two faces, the break candidates.
std::vector<Index> candidates(const Sheet& s) {
    std::vector<Index> out;
    for (Index e = 0; e < s.springs.size(); ++e)
        if (s.springs.kind[e] == SpringKind::Structural && s.springs.breakable[e] &&
            s.springs.faces[e][0] != kNone && s.springs.faces[e][1] != kNone)
            out.push_back(e);
    return out;
}

Index breakRandom(Sheet& s, Rng& rng, double psi) {
    const auto c = candidates(s);
    std::vector<Vec3> n;
    computeVertexNormals(s, n);
    const Index spring = c[static_cast<std::size_t>(rng.uniform() * c.size())];
    return breakEdge(s, spring, n, psi, 0);
}

} // namespace

class TestTopology : public QObject {
    Q_OBJECT

  private slots:
    void manyRandomBreaksKeepAValidMesh() {
        Sheet s = test::makeJitteredSheet(12, 16, 3);
        QCOMPARE(validateSheet(s), std::string());
        const long chi = eulerCharacteristic(s);
        QCOMPARE(chi, 1L); // a disc
        const double mass = totalMass(s);
        Rng rng(11);
        for (int k = 0; k < 400; ++k) {
            breakRandom(s, rng, rng.uniform());
            if (k % 50 == 0) QCOMPARE(validateSheet(s), std::string());
        }
        QCOMPARE(validateSheet(s), std::string()); // every edge has its faces, no degenerate
        QCOMPARE(eulerCharacteristic(s), chi);
        QVERIFY2(std::abs(totalMass(s) - mass) <= 1e-12 * mass,
                 qPrintable(QString::number(std::abs(totalMass(s) - mass) / mass)));
        // Interior edges have exactly two triangles: count triangle-edge incidences.
        std::vector<int> uses(s.springs.size(), 0);
        for (const Triangle& t : s.tris)
            for (Index e : t.e) ++uses[e];
        int boundary = 0;
        for (Index e = 0; e < s.springs.size(); ++e) {
            if (s.springs.kind[e] != SpringKind::Structural) {
                QCOMPARE(uses[e], 0);
                continue;
            }
            QVERIFY(uses[e] == 1 || uses[e] == 2);
            boundary += uses[e] == 1;
        }
        QCOMPARE(boundary, 2 * (12 - 1) + 2 * (16 - 1)); // breaks never touch the boundary
        QCOMPARE(computeStats(s).breaks, 400);
    }

    void breakThenRecoverIsIdentity() {
        Sheet s = test::makeJitteredSheet(8, 10, 5);
        Rng rng(2);
        for (int k = 0; k < 30; ++k) breakRandom(s, rng, 0.5); // not a fresh mesh
        for (int trial = 0; trial < 50; ++trial) {
            const Sheet before = s;
            const Index ev = breakRandom(s, rng, rng.uniform());
            QVERIFY(canRecover(s, ev));
            QVERIFY(recoverEvent(s, ev));
            QString why;
            QVERIFY2(sameSheet(s, before, &why), qPrintable(why));
            QVERIFY(!s.events[ev].active);
            QVERIFY(!canRecover(s, ev)); // a recovered event cannot be recovered twice
        }
    }

    void recoveryRefusesWhenAHalfEdgeBrokeAgain() {
        Sheet s = test::makeJitteredSheet(8, 10, 9);
        const Sheet original = s;
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        const auto c = candidates(s);
        const Index first = breakEdge(s, c[c.size() / 2], n, 0.5, 0);
        computeVertexNormals(s, n);
        const Index ein = s.events[first].springs[0];
        const Index second = breakEdge(s, ein, n, 0.5, 1);
        const Sheet broken = s;
        QVERIFY(!canRecover(s, first));
        QVERIFY(!recoverEvent(s, first));
        QString why;
        QVERIFY2(sameSheet(s, broken, &why), qPrintable(why)); // refused: nothing changed
        // In reverse order both come back, and the sheet is the original again.
        QVERIFY(recoverEvent(s, second));
        QVERIFY(recoverEvent(s, first));
        QVERIFY2(sameSheet(s, original, &why), qPrintable(why));
    }

    void recoveryRefusesWhenANeighbouringTriangleChanged() {
        Sheet s = test::makeJitteredSheet(8, 10, 4);
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        const auto c = candidates(s);
        const Index first = breakEdge(s, c[c.size() / 2], n, 0.5, 0);
        // Break an old edge of one of the four new triangles (not a half-edge).
        const Triangle t = s.tris[s.events[first].tris[0]];
        Index other = kNone;
        for (Index e : t.e)
            if (s.springs.breakable[e] && s.springs.faces[e][1] != kNone &&
                e != s.events[first].springs[0] && e != s.events[first].springs[1])
                other = e;
        QVERIFY(other != kNone);
        computeVertexNormals(s, n);
        breakEdge(s, other, n, 0.5, 1);
        QVERIFY(!canRecover(s, first));
    }

    void outOfOrderRecoveryKeepsAValidMesh() {
        Sheet s = test::makeJitteredSheet(12, 16, 8);
        const Sheet original = s;
        const double mass = totalMass(s);
        Rng rng(5);
        std::vector<Index> events;
        for (int k = 0; k < 120; ++k) events.push_back(breakRandom(s, rng, 0.3));
        // Recover in a shuffled order, retrying the refused ones until none is left.
        int recovered = 0;
        for (int round = 0; round < 200 && recovered < 120; ++round) {
            for (std::size_t k = events.size(); k-- > 1;)
                std::swap(events[k], events[static_cast<std::size_t>(rng.uniform() * (k + 1))]);
            for (Index ev : events)
                if (s.events[ev].active && recoverEvent(s, ev)) {
                    ++recovered;
                    QCOMPARE(validateSheet(s), std::string());
                }
        }
        QCOMPARE(recovered, 120);
        // The original topology (up to vertex and spring numbering of nothing: all inserted
        // elements are gone, so the arrays are back to the original sizes and contents).
        QCOMPARE(s.verts.size(), original.verts.size());
        QCOMPARE(s.springs.size(), original.springs.size());
        QVERIFY(s.tris == original.tris);
        QVERIFY(s.springs.rest == original.springs.rest);
        QVERIFY(std::abs(totalMass(s) - mass) <= 1e-12 * mass);
    }

    // Pins can hold two vertices on one point (the fuzzer found a recording that does).
    // Neither a hinge between them nor a crease of an edge squeezed to nothing may be
    // made: either would be a spring of rest length zero, which no sheet may hold.
    void noSpringIsMadeBetweenCoincidentVertices() {
        Sheet s = test::makeFoldedQuad();
        SimParams p;
        p.hingeThreshold = 0.5;
        s.verts.x[2] = s.verts.x[3] = Vec3(0.0, 0.3, 0.0); // r on l
        QCOMPARE(runHingePass(s, p, 0), 0);
        s.verts.x[3].z() = -1e-9; // parted: the fold gets its hinge
        QCOMPARE(runHingePass(s, p, 1), 1);
        QCOMPARE(validateSheet(s), std::string());

        Sheet squeezed = test::makeFoldedQuad();
        squeezed.verts.x[1] = squeezed.verts.x[0]; // j on i: edge 0 at length zero
        p.phi = 0.0;
        std::vector<Vec3> normals;
        computeVertexNormals(squeezed, normals);
        QCOMPARE(springBreakProbability(squeezed, normals, 0, p), 0.0);
        squeezed.verts.x[1].x() += 1e-6; // barely apart: a candidate again
        computeVertexNormals(squeezed, normals);
        QVERIFY(springBreakProbability(squeezed, normals, 0, p) > 0.0);
    }

    void hingeInsertedWhenFoldClosesAndRecovered() {
        Sheet s = test::makeFoldedQuad();
        SimParams p;
        p.hingeThreshold = 0.5;
        // r-l distance 0.8 of rest 1.0: open enough, no hinge.
        QCOMPARE(runHingePass(s, p, 0), 0);
        // Close the fold: r and l 0.2 apart (< 0.5 · 1.0).
        s.verts.x[2].z() = 0.1;
        s.verts.x[3].z() = -0.1;
        const Sheet open = s;
        QCOMPARE(runHingePass(s, p, 0), 1);
        QCOMPARE(runHingePass(s, p, 1), 0); // one hinge per edge
        QCOMPARE(validateSheet(s), std::string());
        const Index h = s.springs.size() - 1;
        QCOMPARE(s.springs.kind[h], SpringKind::Hinge);
        QVERIFY(std::abs(s.springs.rest[h] - 0.2) < 1e-15); // remembers the fold
        QCOMPARE(computeStats(s).hinges, 1);
        QVERIFY(recoverEvent(s, s.springs.event[h]));
        QString why;
        QVERIFY2(sameSheet(s, open, &why), qPrintable(why));
    }

    void recoveringABreakRemovesHingesOnItsVertex() {
        Sheet s = test::makeJitteredSheet(8, 10, 6);
        const Sheet original = s;
        std::vector<Vec3> n;
        computeVertexNormals(s, n);
        const auto c = candidates(s);
        const Index ev = breakEdge(s, c[c.size() / 2], n, 1.0, 0);
        // Fold everything shut so hinges appear, some of them on n and its springs.
        const Vec3 xn = s.verts.x[s.events[ev].vertex];
        for (Vec3& x : s.verts.x) x = xn + 0.01 * (x - xn);
        SimParams p;
        p.hingeThreshold = 2.0;
        QVERIFY(runHingePass(s, p, 1) > 0);
        QVERIFY(recoverEvent(s, ev));
        QCOMPARE(validateSheet(s), std::string());
        for (Index e = 0; e < s.springs.size(); ++e) {
            QVERIFY(s.springs.a[e] < original.verts.size());
            QVERIFY(s.springs.b[e] < original.verts.size());
        }
        QCOMPARE(s.verts.size(), original.verts.size());
    }

    void everySceneTakesACustomSheetSize() {
        // 15 × 20 cm at 11 vertices across: the sheet, its pins and its arch follow the
        // size (the editor's Advanced size used to be ignored for pinned scenes).
        SceneOptions o;
        o.resolution = 11;
        o.width = 0.15;
        o.length = 0.20;
        for (const std::string& name : sceneNames()) {
            const World w = *makeScene(name, o);
            const Sheet& s = w.sheet;
            QCOMPARE(QString::fromStdString(validateSheet(s)), QString());
            QCOMPARE(s.verts.size(), Index(11 * 14)); // rows: round(10 · 20 / 15) + 1
            double minX = 1, maxX = -1, minZ = 1, maxZ = -1;
            for (const Vec2& X : s.verts.X) {
                minX = std::min(minX, X.x());
                maxX = std::max(maxX, X.x());
                minZ = std::min(minZ, X.y());
                maxZ = std::max(maxZ, X.y());
            }
            QVERIFY(std::abs(maxX - minX - 0.15) < 1e-12 && std::abs(maxZ - minZ - 0.20) < 1e-12);
            if (name == "fold") {
                // The near half is carried over the middle: every vertex beyond the band
                // where the crease forms, and nothing else; the last group holds the far
                // half, beyond the band on the other side, where it lies.
                QCOMPARE(w.script.pins.size(), std::size_t(kCarrySegments + 1));
                Index flap = 0, rest = 0;
                for (const Vec2& X : s.verts.X) {
                    flap += X.y() < -kFoldBand;
                    rest += X.y() > kFoldBand;
                }
                for (std::size_t g = 0; g < kCarrySegments; ++g) {
                    const PinGroup& carry = w.script.pins[g];
                    QCOMPARE(static_cast<Index>(carry.vertices.size()), flap);
                    for (Index i : carry.vertices) QVERIFY(s.verts.X[i].y() < -kFoldBand);
                }
                const PinGroup& held = w.script.pins.back();
                QCOMPARE(static_cast<Index>(held.vertices.size()), rest);
                for (Index i : held.vertices) QVERIFY(s.verts.X[i].y() > kFoldBand);
                QCOMPARE(held.turnRate, 0.0);
                QVERIFY(held.velocity.isZero());
                continue;
            }
            for (const PinGroup& g : w.script.pins)
                for (Index i : g.vertices) {
                    // Pins sit on the sheet's corners (drape), short edges (compress) or
                    // whole rim (crumple-cycles).
                    const Vec2& X = s.verts.X[i];
                    const bool shortEdge = std::abs(std::abs(X.y()) - 0.10) < 1e-12;
                    const bool longEdge = std::abs(std::abs(X.x()) - 0.075) < 1e-12;
                    QVERIFY2(shortEdge || (name == "crumple-cycles" && longEdge), name.c_str());
                }
        }
        // A sheet too short for paper beyond the band on both sides of its middle is not
        // folded: it lies on the desk, unpinned.
        o.width = 0.05;
        o.length = 0.02;
        const World flat = *makeScene("fold", o);
        QVERIFY(flat.script.pins.empty());
        QCOMPARE(std::count(flat.sheet.verts.pinned.begin(), flat.sheet.verts.pinned.end(), 1), 0);
        o.width = 0.001;
        QVERIFY(!makeScene("press", o).has_value());
    }
};

QTEST_APPLESS_MAIN(TestTopology)
#include "test_topology.moc"
