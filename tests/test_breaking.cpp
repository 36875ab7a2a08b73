// Eq. 10 and Eq. 11 against hand-computed values on a constructed configuration.
#include "Breaking.h"
#include "Normals.h"
#include "Params.h"
#include "Rng.h"
#include "SheetBuilder.h"
#include "SheetValidation.h"
#include "TestSheets.h"

#include <QTest>

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

    void stiffPaperReadsTheContractionOnTheArc() {
        // A 4 cm square folded by `fold` along its middle column, the half beyond it
        // turned rigidly about that column, so that every chord keeps its rest length: the
        // paper's soft springs read no contraction at all. Stiff paper (xpbd) reads the
        // arc: an edge whose end normals turn by θ counts as 1 - sin(θ/2)/(θ/2) shorter
        // (docs/model.md, "What a stiff paper's break reads"). Two edges: onto the fold
        // line from the flat half (the line's normals average both halves: θ is about
        // half the fold) and off it into the turned half.
        SheetSpec spec;
        spec.width = spec.length = 0.04;
        spec.columns = spec.rows = 5;
        const auto foldedBy = [&](double fold) {
            Sheet s = buildRectangleSheet(spec);
            for (Index i = 0; i < s.verts.size(); ++i) {
                const double across = s.verts.X[i].x();
                if (across > 0.0)
                    s.verts.x[i] =
                        Vec3(across * std::cos(fold), across * std::sin(fold), s.verts.x[i].z());
            }
            return s;
        };
        const auto springBetween = [](const Sheet& s, Index a, Index b) {
            for (Index k = 0; k < s.springs.size(); ++k)
                if ((s.springs.a[k] == a && s.springs.b[k] == b) ||
                    (s.springs.a[k] == b && s.springs.b[k] == a))
                    return k;
            return kNone;
        };
        const Index row = 2 * spec.columns;
        SimParams stiff;
        stiff.integrator = "xpbd";
        stiff.phi = 0.5;
        SimParams soft = stiff;
        soft.integrator = "jacobi";
        for (const auto& [from, to] : {std::pair{row + 1, row + 2}, std::pair{row + 2, row + 3}}) {
            double previous = 0.0;
            for (const double fold : {0.0, 0.5, 1.5, 2.5}) {
                const Sheet s = foldedBy(fold);
                const Index spring = springBetween(s, from, to);
                QVERIFY(spring != kNone);
                QVERIFY(canBreak(s, spring));
                std::vector<Vec3> n;
                computeVertexNormals(s, n);
                const auto& x = s.verts.x;
                const double l0 = s.springs.rest[spring];
                QVERIFY(std::abs((x[from] - x[to]).norm() - l0) < 1e-12 * l0);
                const double turn = std::acos(std::clamp(n[from].dot(n[to]), -1.0, 1.0));
                QVERIFY(fold == 0.0 || std::abs(turn - 0.5 * fold) < 0.25 * fold);
                const double spanned = turn > 0.0 ? std::sin(turn / 2) / (turn / 2) : 1.0;
                const Index r = s.oppositeVertex(s.springs.faces[spring][0], from, to);
                const Index l = s.oppositeVertex(s.springs.faces[spring][1], from, to);
                const double expected =
                    breakProbability(l0 * spanned, l0, (x[r] - x[l]).norm(), n[from].dot(n[to]),
                                     n[r].dot(n[l]), stiff.phi);
                const double P = springBreakProbability(s, n, spring, stiff);
                QVERIFY2(std::abs(P - expected) < 1e-12,
                         qPrintable(QStringLiteral("fold %1: P %2, by hand %3")
                                        .arg(fold)
                                        .arg(P)
                                        .arg(expected)));
                // The chord reads nothing, flat or folded; the arc grows with the fold.
                QCOMPARE(springBreakProbability(s, n, spring, soft), 0.0);
                if (fold == 0.0)
                    QCOMPARE(P, 0.0);
                else
                    QVERIFY(P > previous);
                previous = P;
            }
        }

        // Peaks are kept in the reading that draws against them: recorded on the arc, a
        // folded sheet at rest draws nothing; recorded on the chord (as before a change
        // to xpbd), every bent edge's whole arc reading would be growth, and it draws.
        for (const bool onTheArc : {true, false}) {
            Sheet s = foldedBy(2.5);
            recordCurrentContraction(s, onTheArc ? stiff : soft);
            Rng rng(7), untouched(7);
            BreakScratch scratch;
            runBreakPass(s, stiff, rng, 0, scratch);
            QCOMPARE(rng.state() == untouched.state(), onTheArc);
        }
    }

    void probabilityPerGrowthComposes() {
        // Growing by g twice must break as often as growing by 2g once: 1-(1-p_g)^2 = p_2g,
        // so the chance of a break does not depend on how many steps the load took.
        const double P = 0.3, ref = 1e-3;
        const double pg = breakProbabilityForGrowth(P, ref / 2, ref);
        QVERIFY(std::abs((1 - (1 - pg) * (1 - pg)) - P) < 1e-15);
        QCOMPARE(breakProbabilityForGrowth(P, ref, ref), P);
        QCOMPARE(breakProbabilityForGrowth(0.0, ref, ref), 0.0);
        // A load carried, not growing, does not break.
        QCOMPARE(breakProbabilityForGrowth(P, 0.0, ref), 0.0);
        QCOMPARE(breakProbabilityForGrowth(P, -ref, ref), 0.0);
    }

    void aHeldLoadDrawsNothingAGrowingOneDrawsAgain() {
        // Eq. 10 draws while an edge's contraction grows past the largest it has carried
        // (docs/model.md, Breaking): however long a load is held, it draws nothing more.
        Sheet s = test::makeJitteredSheet(8, 8, 3);
        for (Vec3& x : s.verts.x) x.x() *= 0.9; // every edge along x now contracted
        SimParams p;
        p.integrator = "jacobi"; // the chord's contraction, as the paper reads it
        p.phi = 0.0;
        p.breakReferenceContraction = 1e9; // draws, but practically never breaks
        Rng rng(1);
        BreakScratch scratch;
        QCOMPARE(runBreakPass(s, p, rng, 0, scratch), 0);
        const auto firstPeaks = s.springs.peakContraction;
        int loaded = 0;
        for (Index k = 0; k < s.springs.size(); ++k)
            if (firstPeaks[k] > 0.0) {
                ++loaded;
                const Vec3 d = s.verts.x[s.springs.a[k]] - s.verts.x[s.springs.b[k]];
                QCOMPARE(firstPeaks[k], 1.0 - d.norm() / s.springs.rest[k]);
            }
        QVERIFY2(loaded > 20, "the squeeze loaded too few edges to show anything");
        const Rng::State held = rng.state();
        for (int step = 1; step <= 100; ++step) QCOMPARE(runBreakPass(s, p, rng, step, scratch), 0);
        QVERIFY2(rng.state() == held, "a load that did not grow drew numbers");
        QVERIFY(s.springs.peakContraction == firstPeaks);
        for (Vec3& x : s.verts.x) x.x() *= 0.99;
        runBreakPass(s, p, rng, 101, scratch);
        QVERIFY2(rng.state() != held, "a growing load drew nothing");
        for (Index k = 0; k < s.springs.size(); ++k)
            QVERIFY(s.springs.peakContraction[k] >= firstPeaks[k]);
    }

    void noBreakSplitsFinerThanTheCreaseSpacing() {
        // Every edge of this sheet is squeezed and Eq. 10 cannot miss (growth beyond any
        // reference), so only the crease spacing decides what may split.
        Sheet s = test::makeJitteredSheet(5, 5, 4);
        SimParams p;
        p.phi = 0.0;
        p.breakReferenceContraction = 1e-12;
        double shortest = 1e9;
        for (Index k = 0; k < s.springs.size(); ++k)
            if (s.springs.kind[k] == SpringKind::Structural)
                shortest = std::min(shortest, s.materialDistance(s.springs.a[k], s.springs.b[k]));
        // Room for one split of the shortest edges, not for two.
        p.material.creaseSpacing = 0.3 * shortest;
        Rng rng(2);
        BreakScratch scratch;
        int breaks = 0;
        for (int step = 0; step < 60; ++step) {
            for (Vec3& x : s.verts.x) x *= 0.995;
            breaks += runBreakPass(s, p, rng, step, scratch);
        }
        QVERIFY2(breaks > 0, "nothing broke, so the spacing was never tested");
        for (Index k = 0; k < s.springs.size(); ++k) {
            if (s.springs.kind[k] != SpringKind::Structural) continue;
            const double l = s.materialDistance(s.springs.a[k], s.springs.b[k]);
            QVERIFY2(l >= p.material.creaseSpacing,
                     qPrintable(QStringLiteral("edge %1 is %2 long in the material, under %3")
                                    .arg(k)
                                    .arg(l)
                                    .arg(p.material.creaseSpacing)));
        }
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

    void paperThatDoesNotStretchBreaksWithoutStretchingTheNewEdges() {
        // The folded quad's edge is pressed to 0.8 of its length while r and l sit at
        // their rest distance from its middle. Eq. 11 as the paper has it sinks n by 0.3,
        // which leaves the edges across (r-n, n-l) 44 % long; paper that does not stretch
        // (keepLengths, xpbd) puts n where none of its four edges is long.
        Sheet paper = test::makeFoldedQuad();
        std::vector<Vec3> n;
        computeVertexNormals(paper, n);
        Sheet soft = paper;
        const auto newEdgeStretch = [](const Sheet& s, Index ev) {
            double worst = -1.0;
            for (Index e : s.events[ev].springs) {
                const double l = (s.verts.x[s.springs.a[e]] - s.verts.x[s.springs.b[e]]).norm();
                worst = std::max(worst, l / s.springs.rest[e] - 1.0);
            }
            return worst;
        };
        const Index asPaper = breakEdge(soft, 0, n, 1.0, 0);
        QVERIFY(std::abs(newEdgeStretch(soft, asPaper) - (std::sqrt(0.52) / 0.5 - 1.0)) < 1e-9);
        const Index stiff = breakEdge(paper, 0, n, 1.0, 0, true);
        QCOMPARE(validateSheet(paper), std::string());
        qInfo("new edges' largest stretch: %.1f %% by Eq. 11, %.2g %% kept",
              100.0 * newEdgeStretch(soft, asPaper), 100.0 * newEdgeStretch(paper, stiff));
        QVERIFY(newEdgeStretch(paper, stiff) < 1e-9);
        // A cell sheared so that r and l lie farther than that from the middle: no point
        // keeps both edges across at their rest length, and neither takes all the excess.
        Sheet sheared = test::makeFoldedQuad();
        sheared.verts.x[2].z() = 0.55;
        sheared.verts.x[3].z() = -0.55;
        computeVertexNormals(sheared, n);
        const Index ev = breakEdge(sheared, 0, n, 1.0, 0, true);
        const Vec3& xn = sheared.verts.x[sheared.events[ev].vertex];
        const double toR = (xn - sheared.verts.x[2]).norm(), toL = (xn - sheared.verts.x[3]).norm();
        qInfo("sheared cell: r-n %.4f, n-l %.4f (rest 0.5, 0.55 at best)", toR, toL);
        QVERIFY(std::abs(toR - toL) < 1e-3);
        QVERIFY(toR < 0.56 && toL < 0.56);
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
