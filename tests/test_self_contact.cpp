// Paper touches itself (sim/SelfContact.h): a layer that comes down on another lies a
// sheet's thickness above it, thrown at up to 10 m/s, and slides on it with friction.
#include "Scenes.h"
#include "SelfContact.h"
#include "SheetStats.h"
#include "Simulation.h"
#include "TriangleGeometry.h"
#include "XpbdIntegrator.h"

#include <QTest>
#include <array>
#include <numbers>

using namespace pf;

namespace {

constexpr double kThickness = 1e-4;

// Two triangles of paper far apart in the material: the lower one flat at y = 0 with
// corners at the origin, 1 cm along x and 1 cm along z (normal +y), and the upper one's
// corners at `upper`, with their masses and places in the material.
Sheet twoTriangles(const std::array<Vec3, 3>& upper, const std::array<double, 3>& masses,
                   const std::array<Vec2, 3>& material) {
    Sheet s;
    const double m = 1e-5;
    s.addVertex(Vec3(0.0, 0.0, 0.0), Vec3::Zero(), m, Vec2(0.0, 0.0));
    s.addVertex(Vec3(0.01, 0.0, 0.0), Vec3::Zero(), m, Vec2(0.01, 0.0));
    s.addVertex(Vec3(0.0, 0.0, 0.01), Vec3::Zero(), m, Vec2(0.0, 0.01));
    for (int k = 0; k < 3; ++k) s.addVertex(upper[k], Vec3::Zero(), masses[k], material[k]);
    s.tris.push_back({{0, 2, 1}, {kNone, kNone, kNone}});
    s.tris.push_back({{3, 5, 4}, {kNone, kNone, kNone}});
    return s;
}

// The lower triangle with the upper one's first corner 0.5 mm over its middle.
Sheet twoLayers() {
    return twoTriangles({Vec3(0.003, 5e-4, 0.003), Vec3(0.03, 5e-4, 0.0), Vec3(0.0, 5e-4, 0.03)},
                        {2e-5, 1e-5, 1e-5}, {Vec2(0.1, 0.1), Vec2(0.13, 0.1), Vec2(0.1, 0.13)});
}

std::vector<double> inverseMasses(const Sheet& s) {
    std::vector<double> w;
    for (double m : s.verts.m) w.push_back(1.0 / m);
    return w;
}

// Height of point p over the plane of triangle t.
double over(const Sheet& s, const std::vector<Vec3>& x, Index t, const Vec3& p) {
    const auto& v = s.tris[t].v;
    const Vec3 n = (x[v[1]] - x[v[0]]).cross(x[v[2]] - x[v[0]]).normalized();
    return (p - x[v[0]]).dot(n);
}

// The editor's sheet with its far half bent round over the near half in a U of radius
// 4 mm, the upper layer 8 mm over the lower one and thrown down at `speed`.
struct UFold {
    World world;
    std::vector<Index> upper;
};

UFold bentOverItself(double speed, bool selfContact) {
    UFold u{*makeScene("press"), {}};
    World& w = u.world;
    w.script = {};
    w.sphere.active = false;
    w.params.breaking = w.params.hinges = false; // an elastic sheet: nothing holds it up
    w.params.selfContact = selfContact;
    auto& V = w.sheet.verts;
    const double r = 0.004, pi = std::numbers::pi;
    for (Index i = 0; i < V.size(); ++i) {
        const double s = V.X[i].y(); // along the length from the middle
        if (s <= 0.0) continue;
        if (s < pi * r) {
            V.x[i] = Vec3(V.X[i].x(), r - r * std::cos(s / r), r * std::sin(s / r));
        } else {
            V.x[i] = Vec3(V.X[i].x(), 2.0 * r, -(s - pi * r));
            V.v[i] = Vec3(0.0, -speed, 0.0);
            u.upper.push_back(i);
        }
    }
    return u;
}

} // namespace

class TestSelfContact : public QObject {
    Q_OBJECT

  private slots:
    void aVertexPushedThroughALayerIsPutBackOnItsSide() {
        const Sheet s = twoLayers();
        const std::vector<double> w = inverseMasses(s);
        SelfContact contact;
        contact.find(s, w, kThickness, std::vector<double>(6, 0.005), 0.0);
        bool found = false;
        for (const SelfContact::Pair& p : contact.pairs())
            if (p.vertex == 3 && p.triangle == 0) found = p.side > 0.0;
        QVERIFY2(found, "the corner over the lower layer is its contact, on its upper side");

        // In one step the corner goes 2 mm through the lower layer, the whole way.
        std::vector<Vec3> x = s.verts.x;
        const std::vector<Vec3> before = x;
        x[3].y() = -2e-3;
        QCOMPARE(contact.crossed(x), std::size_t{1});
        const std::vector<Vec3> pushed = x;
        contact.resolve(x, before, w, 0.5, 0.4, false, 0.0);
        QCOMPARE(contact.crossed(x), std::size_t{0});
        // (The lower layer tilts a little as its corners give way by their weights.)
        qInfo("%.4f mm over the layer", 1e3 * over(s, x, 0, x[3]));
        QVERIFY(std::abs(over(s, x, 0, x[3]) - kThickness) < 0.01 * kThickness);
        // Both layers moved, by their inverse masses: momentum is unchanged.
        Vec3 momentum = Vec3::Zero();
        for (Index i = 0; i < s.verts.size(); ++i) momentum += s.verts.m[i] * (x[i] - pushed[i]);
        QVERIFY(momentum.norm() < 1e-18);
        QVERIFY(x[0].y() < 0.0); // the lower layer gave way too
    }

    // resolve() works a triangle's normal out once for its run of pairs, and again once
    // a pair has moved one of its corners. Two corners of the upper layer lie inside the
    // thickness over the lower one, at two places: the first push tilts the lower layer,
    // and the second must be measured from the tilted plane. The last push of the run
    // leaves its vertex a thickness over the layer as it now lies, to 0.2 nm (the corners'
    // turn as they give way); measured from the plane before the first push, it was
    // 17.8 µm short.
    void aLayerTiltedByOnePushIsMeasuredAsItLiesForTheNext() {
        const Sheet s = twoTriangles(
            {Vec3(0.002, 2e-5, 0.002), Vec3(0.006, 5e-5, 0.002), Vec3(0.004, 5e-5, -0.02)},
            {1e-5, 3.0 * 1e-5, 1e-5}, {Vec2(0.1, 0.1), Vec2(0.14, 0.1), Vec2(0.12, 0.08)});
        const std::vector<double> w = inverseMasses(s);
        SelfContact contact;
        contact.find(s, w, kThickness, std::vector<double>(6, 1e-4), 0.0);
        std::vector<Index> run; // the vertices paired with the lower layer, in order
        for (const SelfContact::Pair& p : contact.pairs())
            if (p.triangle == 0) run.push_back(p.vertex);
        QCOMPARE(run.size(), std::size_t{2});
        std::vector<Vec3> x = s.verts.x;
        const std::vector<Vec3> before = x;
        contact.resolve(x, before, w, 0.0, 0.0, false, 1.0);
        QVERIFY(x[0].y() != 0.0 || x[1].y() != 0.0 || x[2].y() != 0.0); // it tilted
        const double last = over(s, x, 0, x[run.back()]);
        qInfo("the last vertex of the run: %.9f mm over the layer as it lies", 1e3 * last);
        QVERIFY2(std::abs(last - kThickness) < 1e-8, qPrintable(QString::number(last, 'g', 17)));
    }

    void paperInsideTheThicknessPartsSlowlyAndPaperRoundTheEdgeIsLeft() {
        const Sheet s = twoLayers();
        const std::vector<double> w = inverseMasses(s);
        SelfContact contact;
        contact.find(s, w, kThickness, std::vector<double>(6, 0.005), 0.0);
        // Begun 0.02 mm over the layer (the constraints pressed it there), the corner is
        // moved 0.01 mm farther out, not the 0.08 mm to the thickness.
        std::vector<Vec3> previous = s.verts.x;
        previous[3].y() = 2e-5;
        std::vector<Vec3> x = previous;
        contact.resolve(x, previous, w, 0.5, 0.4, false, 1e-5);
        qInfo("%.4f mm over the layer", 1e3 * over(s, x, 0, x[3]));
        QVERIFY(std::abs(over(s, x, 0, x[3]) - 3e-5) < 1e-7);
        // With the lower layer held still: 12 mm under it, farther than the two could
        // have moved toward each other since they were found (5 mm each), the corner came
        // round the layer's edge and is left there; 2 mm under it, it came through.
        std::vector<double> held = w;
        held[0] = held[1] = held[2] = 0.0;
        contact.find(s, held, kThickness, std::vector<double>(6, 0.005), 0.0);
        for (const double depth : {0.012, 0.002}) {
            x = s.verts.x;
            x[3].y() = -depth;
            contact.resolve(x, s.verts.x, held, 0.5, 0.4, false, 0.0);
            qInfo("from %.0f mm under the layer to %.4f mm over it", 1e3 * depth,
                  1e3 * over(s, x, 0, x[3]));
            if (depth > 0.01)
                QCOMPARE(x[3].y(), -depth);
            else
                QVERIFY(std::abs(over(s, x, 0, x[3]) - kThickness) < 1e-12);
        }
    }

    void layersSlideOnEachOtherByCoulombFriction() {
        // The upper corner presses 0.05 mm into the layer's thickness while it slips
        // sideways: a slip within μs times that is undone, a larger one cut by μk times it.
        const Sheet s = twoLayers();
        const std::vector<double> w = inverseMasses(s);
        SelfContact contact;
        contact.find(s, w, kThickness, std::vector<double>(6, 0.005), 0.0);
        const double push = 5e-5, mus = 0.5, muk = 0.4;
        for (const double slip : {0.8 * mus * push, 3.0 * push}) {
            std::vector<Vec3> previous = s.verts.x;
            previous[3].y() = kThickness + 1e-4;
            std::vector<Vec3> x = previous;
            x[3] += Vec3(slip, -1e-4 - push, 0.0);
            // The corner's slip over the triangle's point under it.
            const auto& lower = s.tris[0].v;
            Vec3 b;
            QVERIFY(footBarycentric(x[lower[0]], x[lower[1]], x[lower[2]], x[3], b));
            contact.resolve(x, previous, w, mus, muk, true, 0.0);
            Vec3 under = Vec3::Zero();
            for (int k = 0; k < 3; ++k)
                under += b[k] * (x[lower[static_cast<std::size_t>(k)]] -
                                 previous[lower[static_cast<std::size_t>(k)]]);
            const double left = ((x[3] - previous[3]) - under).x();
            const double expected = slip <= mus * push ? 0.0 : slip - muk * push;
            qInfo("slip %.1f µm: %.3f µm left (expected %.3f)", 1e6 * slip, 1e6 * left,
                  1e6 * expected);
            QVERIFY(std::abs(left - expected) < 1e-9);
            QVERIFY(std::abs(over(s, x, 0, x[3]) - kThickness) < 0.01 * kThickness);
        }
    }

    // The hash's buckets only say where to look: the sheet bent over itself, its upper
    // layer thrown down (allowances of 2 cm there, 1 mm below), gives the same pairs in
    // the same order as walking the cells one by one and taking each vertex where the
    // walk first meets it (the search as it was first written, bucketCells -1), with
    // buckets of one cell, of the allowances' size and of several cells.
    void thePairsDoNotDependOnTheHashsBuckets() {
        const UFold u = bentOverItself(10.0, true);
        const Sheet& s = u.world.sheet;
        std::vector<double> allowance(static_cast<std::size_t>(s.verts.size()), 0.001);
        for (Index v : u.upper) allowance[static_cast<std::size_t>(v)] = 0.02;
        const std::vector<double> w = inverseMasses(s);
        SelfContact one;
        one.find(s, w, kThickness, allowance, 0.0045, -1);
        QVERIFY(one.pairs().size() > 100);
        for (const int bucket : {0, 1, 2, 3, 7}) {
            SelfContact other;
            other.find(s, w, kThickness, allowance, 0.0045, bucket);
            QCOMPARE(other.pairs().size(), one.pairs().size());
            int differing = 0;
            for (std::size_t k = 0; k < one.pairs().size(); ++k) {
                const SelfContact::Pair &p = one.pairs()[k], &q = other.pairs()[k];
                differing += p.vertex != q.vertex || p.triangle != q.triangle ||
                                     p.corners != q.corners || p.side != q.side ||
                                     p.depth != q.depth
                                 ? 1
                                 : 0;
            }
            QCOMPARE(differing, 0);
        }
    }

    // As Box2D's test_determinism.c, for the paper lying on itself: the upper layer
    // thrown onto the lower one at 1 m/s reaches this state after 1 s, bit for bit.
    // The scenes the other determinism tests pin do not press layers together, so a
    // change to the contacts' arithmetic passed them all. A deliberate change of the
    // model updates the hash in the same commit; anything else that changes it is a bug.
    void theThrownLayerReachesItsPinnedHash() {
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        UFold u = bentOverItself(1.0, true);
        Simulation sim(std::move(u.world));
        sim.setThreads(1);
        for (int k = 0; k < 240; ++k) QCOMPARE(sim.step(), StepStatus::Ok);
        const QString hash =
            QStringLiteral("%1").arg(stateHash(sim.world().sheet), 16, 16, QLatin1Char('0'));
        QCOMPARE(hash, QStringLiteral("fc8f2ac0f8b9ac3b"));
    }

    void aFlatSheetIsOneLayer() {
        // Every vertex of a flat sheet lies within reach of the triangles round it, in
        // their plane: none of them is another layer.
        const World w = *makeScene("press");
        SelfContact contact;
        std::vector<double> inverse(static_cast<std::size_t>(w.sheet.verts.size()), 1.0);
        contact.find(w.sheet, inverse, kThickness, std::vector<double>(inverse.size(), 0.005),
                     0.0045);
        QCOMPARE(contact.pairs().size(), std::size_t{0});
    }

    void aLayerThrownOntoAnotherRestsOnIt() {
        // The far half of the sheet, bent over the near half, is thrown down onto it:
        // without self-contact it goes through and lies in the desk with the lower
        // layer; with it, it lies a thickness above, at each speed, and the paper does
        // not stretch for it. (From 8 mm, within the 2 cm a vertex is looked for.)
        if (PAPERFOLD_TEST_SLOWDOWN > 1) QSKIP("physics only; run in the Release build");
        for (const bool touching : {false, true}) {
            for (const double speed : {0.0, 1.0, 10.0}) {
                UFold u = bentOverItself(speed, touching);
                const double t = u.world.params.material.thickness;
                Simulation sim(std::move(u.world));
                double lowest = 1.0, stretch = 0.0;
                for (int k = 0; k < 240; ++k) {
                    QCOMPARE(sim.step(), StepStatus::Ok);
                    stretch = std::max(stretch, computeStats(sim.world().sheet).maxStretch);
                    for (Index i : u.upper)
                        lowest = std::min(lowest, sim.world().sheet.verts.x[i].y());
                }
                int inTheDesk = 0;
                for (Index i : u.upper)
                    if (sim.world().sheet.verts.x[i].y() < 0.5 * t) ++inTheDesk;
                qInfo("self-contact %s, thrown at %.0f m/s: lowest %.3f mm, %d of %zu vertices "
                      "of the upper layer in the lower one after 1 s, stretch %.3f %%",
                      touching ? "on" : "off", speed, 1e3 * lowest, inTheDesk, u.upper.size(),
                      100.0 * stretch);
                if (touching) {
                    // The projection after the sub-steps' contacts may leave a vertex a
                    // little way into the thickness under it, never through.
                    QVERIFY(lowest > 0.8 * t);
                    QCOMPARE(inTheDesk, 0);
                    QVERIFY(stretch < kStretchBound);
                } else {
                    QVERIFY(inTheDesk > static_cast<int>(u.upper.size()) / 2);
                }
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestSelfContact)
#include "test_self_contact.moc"
