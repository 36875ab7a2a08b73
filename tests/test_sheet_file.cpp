// .paper files: exact round trip, exact resume, and refusal of every kind of bad file.
#include "BoundedCbor.h"
#include "Breaking.h"
#include "EditSession.h"
#include "JacobiScene.h"
#include "RecordingFile.h"
#include "Scenes.h"
#include "SheetBuilder.h"
#include "SheetFile.h"
#include "SheetStats.h"
#include "Simulation.h"
#include "TestSheets.h"

#include <QCborArray>
#include <QCborMap>
#include <QCborValue>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>
#include <bit>
#include <cstring>
#include <functional>
#include <limits>

using namespace pf;

namespace {

// A press run with breaks, hinges and some recovered events (the paper's jacobi, whose
// free sheet breaks under the sphere; xpbd's slides).
World crumpledWorld(int steps) {
    Simulation sim(test::jacobiScene("press"));
    for (int k = 0; k < steps; ++k) sim.step();
    Sheet& s = sim.world().sheet;
    // Recover the newest two breaks so the log holds inactive entries too.
    int recovered = 0;
    for (Index e = static_cast<Index>(s.events.size()) - 1; e >= 0 && recovered < 2; --e)
        if (s.events[e].kind == EventKind::Break && recoverEvent(s, e)) ++recovered;
    return sim.world();
}

void compareEvents(const std::vector<DamageEvent>& a, const std::vector<DamageEvent>& b) {
    QCOMPARE(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        QCOMPARE(a[k].kind, b[k].kind);
        QCOMPARE(a[k].active, b[k].active);
        QCOMPARE(a[k].step, b[k].step);
        QCOMPARE(a[k].edge, b[k].edge);
        QCOMPARE(a[k].vertex, b[k].vertex);
        QVERIFY(a[k].springs == b[k].springs);
        QVERIFY(a[k].tris == b[k].tris);
        QVERIFY(a[k].oldTris == b[k].oldTris);
        QVERIFY(a[k].newTris == b[k].newTris);
        QVERIFY(a[k].massTaken == b[k].massTaken);
    }
}

// Saves the run as it is now and loads it back, the xpbd state unchanged, as a run of
// its own.
void keepResumable(const Simulation& whole, std::vector<Simulation>& resumed) {
    const WorldLoad l = decodeWorld(encodeWorld(whole.world()));
    QVERIFY2(l.world, qPrintable(l.error));
    QVERIFY(l.world->sheet.paper == whole.world().sheet.paper);
    resumed.emplace_back(*l.world);
}

// Steps each resumed run to where the whole run is: each ends there bit for bit, asleep
// or not as it is.
void expectEachToEndAsTheWhole(std::vector<Simulation>& resumed, const Simulation& whole) {
    for (Simulation& r : resumed) {
        while (r.world().stepCount < whole.world().stepCount) QCOMPARE(r.step(), StepStatus::Ok);
        QCOMPARE(r.asleep(), whole.asleep());
        QCOMPARE(encodeWorld(r.world()), encodeWorld(whole.world()));
    }
}

QByteArray validFile() {
    static const QByteArray bytes = encodeWorld(crumpledWorld(300));
    return bytes;
}

// Re-encodes the file with one field of one map replaced.
QByteArray withField(const QStringList& path, const QCborValue& value) {
    std::function<QCborValue(QCborValue, int)> set = [&](QCborValue node, int depth) {
        QCborMap m = node.toMap();
        if (depth + 1 == path.size())
            m[path[depth]] = value;
        else
            m[path[depth]] = set(m[path[depth]], depth + 1);
        return QCborValue(m);
    };
    return set(QCborValue::fromCbor(validFile()), 0).toCbor();
}

// A sheet byte array with element `index` (of `width` bytes) overwritten.
QByteArray withBytes(const char* field, qsizetype offset, const QByteArray& replacement) {
    QByteArray b = QCborValue::fromCbor(validFile())
                       .toMap()[QLatin1String("sheet")]
                       .toMap()[QLatin1String(field)]
                       .toByteArray();
    b.replace(offset, replacement.size(), replacement);
    return withField({"sheet", QString::fromLatin1(field)}, b);
}

QByteArray le32(qint32 v) {
    const auto le = qToLittleEndian(v);
    return QByteArray(reinterpret_cast<const char*>(&le), 4);
}

QByteArray f64s(std::initializer_list<double> values) {
    QByteArray out;
    for (double v : values) {
        const auto le = qToLittleEndian(std::bit_cast<quint64>(v));
        out.append(reinterpret_cast<const char*>(&le), 8);
    }
    return out;
}

// The valid file with the xpbd state of its sheet replaced.
QByteArray withPaperState(qint64 plasticCount, const QByteArray& plastic, qint64 gripCount,
                          const QByteArray& grips) {
    QCborMap root = QCborValue::fromCbor(validFile()).toMap();
    QCborMap sheet = root[QLatin1String("sheet")].toMap();
    sheet[QLatin1String("plasticCount")] = plasticCount;
    sheet[QLatin1String("plastic")] = plastic;
    sheet[QLatin1String("gripCount")] = gripCount;
    sheet[QLatin1String("grips")] = grips;
    root[QLatin1String("sheet")] = sheet;
    return QCborValue(root).toCbor();
}

QByteArray plasticBend(std::initializer_list<qint32> vertices) {
    QByteArray out;
    for (qint32 v : vertices) out += le32(v);
    return out + f64s({0.0, 1.0, 0.0});
}

QByteArray toolGrip(qint32 triangle, double b0, double b1, double b2) {
    return le32(triangle) + f64s({b0, b1, b2, 0.0, -0.04, 0.0});
}

} // namespace

class TestSheetFile : public QObject {
    Q_OBJECT

  private slots:
    void roundTripIsExactFieldByField() {
        const World w = crumpledWorld(300);
        const auto st = computeStats(w.sheet);
        QVERIFY(st.breaks > 0);
        QVERIFY(st.recoveries > 0);
        const WorldLoad l = decodeWorld(encodeWorld(w));
        QVERIFY2(l.world, qPrintable(l.error));
        const World& r = *l.world;
        QCOMPARE(r.scene, w.scene);
        QCOMPARE(r.seed, w.seed);
        QVERIFY(r.rng.state() == w.rng.state());
        QCOMPARE(r.time, w.time);
        QCOMPARE(r.stepCount, w.stepCount);
        QVERIFY(r.sheet.verts.x == w.sheet.verts.x);
        QVERIFY(r.sheet.verts.v == w.sheet.verts.v);
        QVERIFY(r.sheet.verts.m == w.sheet.verts.m);
        QVERIFY(r.sheet.verts.X == w.sheet.verts.X);
        QVERIFY(r.sheet.verts.pinned == w.sheet.verts.pinned);
        QVERIFY(r.sheet.springs.a == w.sheet.springs.a);
        QVERIFY(r.sheet.springs.b == w.sheet.springs.b);
        QVERIFY(r.sheet.springs.rest == w.sheet.springs.rest);
        QVERIFY(r.sheet.springs.kind == w.sheet.springs.kind);
        QVERIFY(r.sheet.springs.breakable == w.sheet.springs.breakable);
        QVERIFY(r.sheet.springs.hinged == w.sheet.springs.hinged);
        QVERIFY(r.sheet.springs.faces == w.sheet.springs.faces);
        QVERIFY(r.sheet.springs.event == w.sheet.springs.event);
        QVERIFY(r.sheet.springs.peakContraction == w.sheet.springs.peakContraction);
        QVERIFY(r.sheet.tris == w.sheet.tris);
        QCOMPARE(r.sheet.density, w.sheet.density);
        compareEvents(r.sheet.events, w.sheet.events);
        QCOMPARE(r.params.breakReferenceContraction, w.params.breakReferenceContraction);
        QCOMPARE(r.params.phi, w.params.phi);
        QCOMPARE(r.params.psi, w.params.psi);
        QCOMPARE(r.params.sigma, w.params.sigma);
        QCOMPARE(r.params.dt, w.params.dt);
        QCOMPARE(r.params.iterations, w.params.iterations);
        QCOMPARE(r.params.integrator, w.params.integrator);
        QVERIFY(r.params.stiffness == w.params.stiffness);
        QVERIFY(r.params.damping == w.params.damping);
        QCOMPARE(r.sphere.center, w.sphere.center);
        QCOMPARE(r.sphere.velocity, w.sphere.velocity);
        QCOMPARE(r.sphere.radius, w.sphere.radius);
        QCOMPARE(r.script.sphereKeys.size(), w.script.sphereKeys.size());
        QCOMPARE(r.script.pins.size(), w.script.pins.size());
        // And encoding is a function of the state: the bytes come back identical.
        QCOMPARE(encodeWorld(r), encodeWorld(w));
    }

    // The paper and the xpbd settings travel with the sheet; a file written before they
    // existed (no such keys) loads as office paper with the defaults.
    void materialRoundTripsAndOldFilesGetOfficePaper() {
        World w = *makeScene("drape");
        w.params.integrator = "xpbd";
        w.params.substeps = 12;
        w.params.bendingDamping = 0.02;
        w.params.toolForce = 3.5;
        w.params.selfContact = false;
        Material card;
        QVERIFY(materialPreset("card", card));
        setMaterial(w, card);
        const WorldLoad l = decodeWorld(encodeWorld(w));
        QVERIFY2(l.world, qPrintable(l.error));
        QVERIFY(l.world->params.material == card);
        QCOMPARE(l.world->params.substeps, 12);
        QCOMPARE(l.world->params.bendingDamping, 0.02);
        QCOMPARE(l.world->params.toolForce, 3.5);
        QVERIFY(!l.world->params.selfContact);
        QVERIFY(l.world->sheet.verts.m == w.sheet.verts.m);

        QCborMap root = QCborValue::fromCbor(encodeWorld(*makeScene("press"))).toMap();
        QCborMap params = root[QLatin1String("params")].toMap();
        for (const char* key : {"material", "substeps", "bendingDamping", "toolForce"})
            params.remove(QLatin1String(key));
        root[QLatin1String("params")] = params;
        const WorldLoad old = decodeWorld(QCborValue(root).toCbor());
        QVERIFY2(old.world, qPrintable(old.error));
        QVERIFY(old.world->params.material == Material{});
        QCOMPARE(old.world->params.substeps, SimParams{}.substeps);
        QCOMPARE(old.world->params.toolForce, SimParams{}.toolForce);
        // A material written before plastic bending (no yieldCurvature), or before the
        // crease spacing, takes its preset's value.
        for (const char* key : {"yieldCurvature", "creaseSpacing"}) {
            QCborMap cardRoot = QCborValue::fromCbor(encodeWorld(w)).toMap();
            QCborMap cardParams = cardRoot[QLatin1String("params")].toMap();
            QCborMap cardMaterial = cardParams[QLatin1String("material")].toMap();
            cardMaterial.remove(QLatin1String(key));
            cardParams[QLatin1String("material")] = cardMaterial;
            cardRoot[QLatin1String("params")] = cardParams;
            const WorldLoad oldCard = decodeWorld(QCborValue(cardRoot).toCbor());
            QVERIFY2(oldCard.world, qPrintable(oldCard.error));
            QVERIFY(oldCard.world->params.material == card);
        }
        QVERIFY(card.creaseSpacing != Material{}.creaseSpacing);
        // One written before self-contact has neither the paper's thickness nor its
        // friction on itself: it takes its preset's, and its layers touch.
        {
            QCborMap cardRoot = QCborValue::fromCbor(encodeWorld(w)).toMap();
            QCborMap cardParams = cardRoot[QLatin1String("params")].toMap();
            QCborMap cardMaterial = cardParams[QLatin1String("material")].toMap();
            for (const char* key : {"thickness", "paperStaticFriction", "paperKineticFriction"})
                cardMaterial.remove(QLatin1String(key));
            cardParams[QLatin1String("material")] = cardMaterial;
            cardParams.remove(QLatin1String("selfContact"));
            cardRoot[QLatin1String("params")] = cardParams;
            const WorldLoad oldCard = decodeWorld(QCborValue(cardRoot).toCbor());
            QVERIFY2(oldCard.world, qPrintable(oldCard.error));
            QVERIFY(oldCard.world->params.material == card);
            QVERIFY(oldCard.world->params.selfContact);
        }
        QVERIFY(card.thickness != Material{}.thickness);
        QVERIFY(card.paperStaticFriction != Material{}.paperStaticFriction);
    }

    // A file is one sheet: bytes after it (two files joined, zeros appended) were read
    // without a word, and a sheet padded with 500 MB of zeros loaded.
    void bytesAfterTheSheetAreRefused() {
        const QByteArray sheet = encodeWorld(*makeScene("press"));
        QVERIFY(decodeWorld(sheet).world);
        for (const QByteArray& more : {QByteArray(2, '\0'), sheet}) {
            const WorldLoad l = decodeWorld(sheet + more);
            QVERIFY(!l.world);
            QVERIFY2(l.error.contains(QStringLiteral("goes on for %1 bytes").arg(more.size())),
                     qPrintable(l.error));
        }
    }

    // The names a file holds are shown and printed: a scene named with a terminal's
    // escape sequence was printed raw by `simulate`.
    void controlCharactersInANameAreRefused() {
        QCborMap root = QCborValue::fromCbor(encodeWorld(*makeScene("press"))).toMap();
        root[QLatin1String("scene")] = QStringLiteral("press\n\x1b[31mred");
        const WorldLoad l = decodeWorld(QCborValue(root).toCbor());
        QVERIFY(!l.world);
        QVERIFY2(l.error.contains(QLatin1String("file.scene: a control character (U+000a)")),
                 qPrintable(l.error));
        root[QLatin1String("scene")] = QStringLiteral("pressé 紙");
        QVERIFY(decodeWorld(QCborValue(root).toCbor()).world);
    }

    // Negative integers are read as written: Qt gives a CBOR negative integer's
    // magnitude, and read as CBOR's "-1 - n" a gravity of -5 written as an integer (by
    // hand, or by another program) loaded as -6, and a step of -1 was refused as -2.
    void negativeIntegersAreReadAsWritten() {
        QCborMap root = QCborValue::fromCbor(encodeWorld(*makeScene("press"))).toMap();
        QCborMap params = root[QLatin1String("params")].toMap();
        params[QLatin1String("gravity")] = qint64(-5);
        root[QLatin1String("params")] = params;
        QCborMap ground = root[QLatin1String("ground")].toMap();
        ground[QLatin1String("height")] = qint64(-1);
        root[QLatin1String("ground")] = ground;
        const WorldLoad l = decodeWorld(QCborValue(root).toCbor());
        QVERIFY2(l.world, qPrintable(l.error));
        QCOMPARE(l.world->params.gravity, -5.0);
        QCOMPARE(l.world->groundHeight, -1.0);
        root[QLatin1String("step")] = qint64(-1);
        const WorldLoad bad = decodeWorld(QCborValue(root).toCbor());
        QVERIFY(!bad.world);
        QVERIFY2(bad.error.contains(QLatin1String(": -1 is outside")), qPrintable(bad.error));
        // The extremes: -2⁶³ as an integer, -2⁶⁴ (CBOR's most negative) as a number.
        CborBounds bounds;
        QString error;
        const auto least = parseBoundedCbor(QCborValue(std::numeric_limits<qint64>::min()).toCbor(),
                                            bounds, &error);
        QVERIFY2(least, qPrintable(error));
        QCOMPARE(least->toInteger(), std::numeric_limits<qint64>::min());
        const auto most =
            parseBoundedCbor(QByteArray::fromHex("3bffffffffffffffff"), bounds, &error);
        QVERIFY2(most, qPrintable(error));
        QCOMPARE(most->toDouble(), -18446744073709551616.0);
        // A step near the largest integer overflowed as the sheet stepped on.
        root[QLatin1String("step")] = std::numeric_limits<qint64>::max();
        const WorldLoad late = decodeWorld(QCborValue(root).toCbor());
        QVERIFY(!late.world);
        QVERIFY2(late.error.contains(QLatin1String("file.step")), qPrintable(late.error));
    }

    // A sheet saved before breaks followed loading has no peak contractions: it counts
    // as having carried the load it lies under (so a held load draws nothing more, as
    // test_breaking shows), instead of breaking wherever an edge is compressed.
    void aFileWithoutPeaksCountsTheLoadItCarries() {
        const World w = crumpledWorld(300);
        QCborMap root = QCborValue::fromCbor(encodeWorld(w)).toMap();
        QCborMap sheet = root[QLatin1String("sheet")].toMap();
        QVERIFY(sheet.contains(QLatin1String("peakContraction")));
        sheet.remove(QLatin1String("peakContraction"));
        root[QLatin1String("sheet")] = sheet;
        QCborMap params = root[QLatin1String("params")].toMap();
        params.remove(QLatin1String("breakReferenceContraction"));
        root[QLatin1String("params")] = params;
        const WorldLoad old = decodeWorld(QCborValue(root).toCbor());
        QVERIFY2(old.world, qPrintable(old.error));
        QCOMPARE(old.world->params.breakReferenceContraction,
                 SimParams{}.breakReferenceContraction);
        const Sheet& s = old.world->sheet;
        int compressed = 0;
        for (Index k = 0; k < s.springs.size(); ++k) {
            const double l = (s.verts.x[s.springs.a[k]] - s.verts.x[s.springs.b[k]]).norm();
            const double contraction = 1.0 - l / s.springs.rest[k];
            QCOMPARE(s.springs.peakContraction[k], std::max(contraction, 0.0));
            compressed += contraction > 0.0;
        }
        QVERIFY(compressed > 0);
    }

    void recoveryWorksOnALoadedSheet() {
        World r = *decodeWorld(validFile()).world;
        Sheet& s = r.sheet;
        Index last = kNone;
        for (Index e = 0; e < static_cast<Index>(s.events.size()); ++e)
            if (s.events[e].active && s.events[e].kind == EventKind::Break) last = e;
        QVERIFY(last != kNone);
        QVERIFY(recoverEvent(s, last));
    }

    // The fold scene's flap turns about an axis and is let go at a time: saved mid-turn,
    // the sheet resumes bit for bit through the turn and the release; a turn about a
    // non-unit axis is refused.
    void aTurningPinGroupResumesExactly() {
        Simulation whole(test::machineryScene("fold"));
        for (int k = 0; k < 200; ++k) QCOMPARE(whole.step(), StepStatus::Ok);
        const QByteArray saved = encodeWorld(whole.world());
        WorldLoad l = decodeWorld(saved);
        QVERIFY2(l.world, qPrintable(l.error));
        const PinGroup& g = l.world->script.pins.front();
        QCOMPARE(g.turnRate, whole.world().script.pins.front().turnRate);
        QCOMPARE(g.release, whole.world().script.pins.front().release);
        Simulation resumed(std::move(*l.world));
        while (whole.world().time < g.release + 0.5) {
            QCOMPARE(whole.step(), StepStatus::Ok);
            QCOMPARE(resumed.step(), StepStatus::Ok);
        }
        QVERIFY(!whole.world().sheet.verts.pinned[g.vertices.front()]); // let go
        QCOMPARE(encodeWorld(resumed.world()), encodeWorld(whole.world()));

        QCborMap root = QCborValue::fromCbor(saved).toMap();
        QCborMap script = root[QLatin1String("script")].toMap();
        QCborArray pins = script[QLatin1String("pins")].toArray();
        QCborMap group = pins.at(0).toMap();
        QByteArray axis(24, '\0');
        const double two = 2.0;
        std::memcpy(axis.data(), &two, 8);
        group[QLatin1String("axis")] = axis;
        pins[0] = group;
        script[QLatin1String("pins")] = pins;
        root[QLatin1String("script")] = script;
        const WorldLoad bad = decodeWorld(QCborValue(root).toCbor());
        QVERIFY(!bad.world);
        QVERIFY2(bad.error.contains(QStringLiteral("axis")), qPrintable(bad.error));
    }

    // The crumple-cycles rim is drawn in toward a point and out again: saved mid-draw, the
    // sheet resumes bit for bit into the next cycle; a draw without its point, or at an
    // absurd rate, is refused.
    void aDrawingPinGroupResumesExactly() {
        Simulation whole(test::machineryScene("crumple-cycles"));
        for (int k = 0; k < 150; ++k) QCOMPARE(whole.step(), StepStatus::Ok);
        const QByteArray saved = encodeWorld(whole.world());
        WorldLoad l = decodeWorld(saved);
        QVERIFY2(l.world, qPrintable(l.error));
        const PinGroup& g = l.world->script.pins.front();
        QCOMPARE(g.scaleRate, whole.world().script.pins.front().scaleRate);
        QCOMPARE(g.pivot, whole.world().script.pins.front().pivot);
        QVERIFY(g.scaleRate < 0.0);
        Simulation resumed(std::move(*l.world));
        while (whole.world().time < kCrumpleCycleSeconds + 0.5) {
            QCOMPARE(whole.step(), StepStatus::Ok);
            QCOMPARE(resumed.step(), StepStatus::Ok);
        }
        QCOMPARE(encodeWorld(resumed.world()), encodeWorld(whole.world()));

        const auto withGroup = [&](const std::function<void(QCborMap&)>& change) {
            QCborMap root = QCborValue::fromCbor(saved).toMap();
            QCborMap script = root[QLatin1String("script")].toMap();
            QCborArray pins = script[QLatin1String("pins")].toArray();
            QCborMap group = pins.at(0).toMap();
            change(group);
            pins[0] = group;
            script[QLatin1String("pins")] = pins;
            root[QLatin1String("script")] = script;
            return decodeWorld(QCborValue(root).toCbor());
        };
        const WorldLoad noPivot = withGroup([](QCborMap& g) { g.remove(QLatin1String("pivot")); });
        QVERIFY(!noPivot.world);
        QVERIFY2(noPivot.error.contains(QStringLiteral("pivot")), qPrintable(noPivot.error));
        const WorldLoad fast = withGroup([](QCborMap& g) { g[QLatin1String("scaleRate")] = 1e6; });
        QVERIFY(!fast.world);
        QVERIFY2(fast.error.contains(QStringLiteral("scaleRate")), qPrintable(fast.error));
    }

    void resumeIsExact() {
        Simulation whole(test::machineryScene("press"));
        Simulation first(test::machineryScene("press"));
        for (int k = 0; k < 300; ++k) {
            whole.step();
            first.step();
        }
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("half.paper"));
        QString error;
        QVERIFY2(saveWorld(first.world(), path, &error), qPrintable(error));
        WorldLoad l = loadWorld(path);
        QVERIFY2(l.world, qPrintable(l.error));
        Simulation resumed(std::move(*l.world));
        for (int k = 0; k < 300; ++k) {
            whole.step();
            resumed.step();
        }
        QVERIFY(computeStats(whole.world().sheet).breaks > 0);
        QCOMPARE(stateHash(resumed.world().sheet), stateHash(whole.world().sheet));
        QCOMPARE(encodeWorld(resumed.world()), encodeWorld(whole.world()));
    }

    void xpbdResumesExactlyWithItsFoldsAndGrips() {
        // The xpbd integrator carries plastic folds, the tool's grips and the sleep
        // counter from step to step; saved with the sheet, a run resumed from a file
        // mid-stroke continues bit for bit.
        // The sheet's far edge is held, and this paper yields at a 1 m radius, so that
        // the tool's push leaves plastic bends as well as grips.
        World start = *makeScene("press");
        start.params.integrator = "xpbd";
        start.params.material.yieldCurvature = 1.0;
        test::holdFarEdge(start, 19);
        // Saved mid-stroke (at the first step from the 100th at which the tool holds the
        // paper; its grips come and go as it ploughs) and after the tool has left (a fold
        // has yielded), each resumed run ends where the whole run does.
        Simulation whole(start);
        std::vector<Simulation> resumed;
        bool sawGrips = false, sawPlastic = false;
        // A sanitized build (looking for memory errors, 10-20 times slower) compares the
        // runs 10 steps after the last save; the Release build, 200 steps after it.
        const int lastStep = PAPERFOLD_TEST_SLOWDOWN > 1 ? 260 : 450;
        for (int k = 1; k <= lastStep; ++k) {
            QCOMPARE(whole.step(), StepStatus::Ok);
            const PaperState& state = whole.world().sheet.paper;
            constexpr int kToolLifted = 228; // the sphere's path leaves the paper at 0.95 s
            const bool midStroke = !sawGrips && k >= 100 && k < kToolLifted && !state.grips.empty();
            if (!midStroke && k != 250) continue;
            sawGrips = sawGrips || !state.grips.empty();
            sawPlastic = sawPlastic || !state.plastic.empty();
            keepResumable(whole, resumed);
        }
        QVERIFY2(sawGrips, "the tool held nothing at a save");
        QVERIFY2(sawPlastic, "nothing had yielded at a save");
        // Undoing a break renumbers vertices; the plastic bends follow, and the sheet
        // still saves and loads.
        World undone = whole.world();
        Index lastBreak = kNone;
        for (Index e = 0; e < static_cast<Index>(undone.sheet.events.size()); ++e)
            if (undone.sheet.events[e].active && undone.sheet.events[e].kind == EventKind::Break)
                lastBreak = e;
        if (lastBreak != kNone && recoverEvent(undone.sheet, lastBreak)) {
            const WorldLoad back = decodeWorld(encodeWorld(undone));
            QVERIFY2(back.world, qPrintable(back.error));
        }
        expectEachToEndAsTheWhole(resumed, whole);
    }

    void xpbdResumesExactlyWhileItSettlesOnTheDesk() {
        // A sheet that lands on the desk carries, from step to step, how fast it slid
        // across it (sim/DeskHold.h) and where it began to settle: saved while it slides
        // and while it settles, it resumes bit for bit and falls asleep at the same step.
        World start = *makeScene("drop");
        start.params.integrator = "xpbd";
        Simulation whole(start);
        std::vector<Simulation> resumed;
        bool sawSlide = false, sawSettling = false;
        for (int k = 1; k <= 150; ++k) {
            QCOMPARE(whole.step(), StepStatus::Ok);
            const PaperState& state = whole.world().sheet.paper;
            const bool sliding = !sawSlide && state.deskSlide > 1e-3; // 1 mm/s
            // (The still rule reads the vertices' mean positions, which follow a sheet that
            // has just landed some steps late: the quiet rule puts this one to sleep first.)
            const bool settling = !sawSettling && state.still.steps > 3 && !whole.asleep();
            if (!sliding && !settling) continue;
            sawSlide = sawSlide || sliding;
            sawSettling = sawSettling || settling;
            keepResumable(whole, resumed);
        }
        QVERIFY2(sawSlide, "the sheet never slid on the desk");
        QVERIFY2(sawSettling, "the sheet never settled");
        QVERIFY(whole.asleep());
        expectEachToEndAsTheWhole(resumed, whole);
    }

    void xpbdResumesExactlyWhileItTurnsOnOnePin() {
        // A sheet hanging from one pin onto the desk carries how fast it turned about the
        // pin (sim/DeskHold.h, in the slide's place): saved while that is watched, it
        // resumes bit for bit (read back as not watched, the first step would take the
        // turn it measured as it came instead of bounding it).
        World start = makeEditorScene("drape", SceneOptions{}, 0.03);
        start.params.integrator = "xpbd";
        auto& V = start.sheet.verts;
        Index freed = -1;
        for (Index i = 0; i < V.size(); ++i)
            if (V.pinned[i]) freed = i;
        QVERIFY(freed >= 0);
        V.pinned[freed] = 0;
        Simulation whole(start);
        std::vector<Simulation> resumed;
        for (int k = 1; k <= 1200 && resumed.size() < 2; ++k) {
            QCOMPARE(whole.step(), StepStatus::Ok);
            if (whole.world().sheet.paper.deskSlide != kSlideUnknown && k % 40 == 0)
                keepResumable(whole, resumed);
        }
        QVERIFY2(resumed.size() == 2, "the turn was never watched");
        for (int k = 0; k < 120; ++k) QCOMPARE(whole.step(), StepStatus::Ok);
        expectEachToEndAsTheWhole(resumed, whole);
    }

    void filesFromBeforeTheStillStateLoad() {
        // A file without the still state or the slide (saved before they existed) loads
        // as a sheet that has just begun to settle, whose slide was not measured.
        World w = *makeScene("drop");
        w.params.integrator = "xpbd";
        Simulation sim(w);
        for (int k = 0; k < 40; ++k) QCOMPARE(sim.step(), StepStatus::Ok);
        QVERIFY(!sim.world().sheet.paper.still.from.empty());
        QVERIFY(!sim.world().sheet.paper.slowStill.from.empty());
        QCborMap root = QCborValue::fromCbor(encodeWorld(sim.world())).toMap();
        QCborMap sheet = root[QLatin1String("sheet")].toMap();
        for (const char* key :
             {"stillSteps", "stillFromCount", "stillFrom", "stillMeanCount", "stillMean",
              "slowStillSteps", "slowStillFromCount", "slowStillFrom", "slowStillMeanCount",
              "slowStillMean", "deskSlide"}) {
            QVERIFY(sheet.contains(QLatin1String(key)));
            sheet.remove(QLatin1String(key));
        }
        root[QLatin1String("sheet")] = sheet;
        const WorldLoad l = decodeWorld(QCborValue(root).toCbor());
        QVERIFY2(l.world, qPrintable(l.error));
        const PaperState& p = l.world->sheet.paper;
        for (const PaperState::StillWatch* watch : {&p.still, &p.slowStill}) {
            QCOMPARE(watch->steps, 0);
            QVERIFY(watch->from.empty());
            QVERIFY(watch->mean.empty());
        }
        QCOMPARE(p.deskSlide, kSlideUnknown);
        QCOMPARE(p.quietSteps, sim.world().sheet.paper.quietSteps);
        Simulation resumed(*l.world);
        for (int k = 0; k < 240 && !resumed.asleep(); ++k) QCOMPARE(resumed.step(), StepStatus::Ok);
        QVERIFY(resumed.asleep());
    }

    void saveIsAtomicAndFailsCleanly() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("sheet.paper"));
        QString error;
        const World w = *makeScene("drape");
        QVERIFY(saveWorld(w, path, &error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray before = f.readAll();
        f.close();
        // A save that cannot complete leaves nothing half-written behind.
        QVERIFY(!saveWorld(w, dir.filePath(QStringLiteral("missing/dir/x.paper")), &error));
        QVERIFY2(error.contains(QStringLiteral("does not exist")), qPrintable(error));
        // Overwriting replaces the whole file (no tail of the old one left).
        QVERIFY(saveWorld(*makeScene("press"), path, &error));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray after = f.readAll();
        QVERIFY(after != before);
        QVERIFY(decodeWorld(after).world);
        // No temporary files left, hidden ones included.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1);
    }

    void loadingAMissingFileSaysSo() {
        const WorldLoad l = loadWorld(QStringLiteral("/nonexistent/sheet.paper"));
        QVERIFY(!l.world);
        QVERIFY(l.error.contains(QStringLiteral("cannot open")));
    }

    void brokenFilesAreRefusedWithAMessage_data() {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("empty") << QByteArray() << "empty";
        // Other kinds of files say what they are not (a short text file read "cut short").
        QTest::newRow("a text file")
            << QByteArray("hello, I am a text file\n") << "not a PaperFold sheet";
        QTest::newRow("a short text file") << QByteArray("vm\n") << "not a PaperFold sheet";
        QTest::newRow("a picture")
            << QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16) << "not a PaperFold sheet";
        QTest::newRow("wrong magic")
            << withField({"magic"}, QStringLiteral("PaperFold shoot")) << "magic";
        // A recording given where a sheet belongs said "wrong magic"; it says what it is.
        QTest::newRow("a recording")
            << encodeRecording(EditSession(*makeScene("drape")).log()) << "`paperfold replay`";
        QTest::newRow("wrong version") << withField({"version"}, 99) << "version 99";
        QTest::newRow("version as text")
            << withField({"version"}, QStringLiteral("1")) << "version";
        QTest::newRow("missing params") << withField({"params"}, QCborValue()) << "params";
        QTest::newRow("phi out of range") << withField({"params", "phi"}, 7.0) << "phi";
        QTest::newRow("dt is NaN") << withField({"params", "dt"}, qQNaN()) << "dt";
        QTest::newRow("unknown integrator")
            << withField({"params", "integrator"}, QStringLiteral("rk4")) << "rk4";
        QTest::newRow("plastic bend on a missing vertex")
            << withPaperState(1, plasticBend({0, 1, 999999, -1, -1}), 0, {})
            << "plastic bend names a vertex";
        QTest::newRow("plastic bend with a gap")
            << withPaperState(1, plasticBend({0, -1, 1, 2, -1}), 0, {}) << "gap";
        QTest::newRow("plastic bend repeating a vertex")
            << withPaperState(1, plasticBend({0, 1, 1, -1, -1}), 0, {}) << "repeats";
        QTest::newRow("two grips on one triangle")
            << withPaperState(0, {}, 2, toolGrip(0, 1, 0, 0) + toolGrip(0, 0, 1, 0))
            << "repeated triangle";
        QTest::newRow("grip off its triangle")
            << withPaperState(0, {}, 1, toolGrip(0, 1, 1, 0)) << "tool grip is malformed";
        QTest::newRow("more grips than triangles")
            << withPaperState(0, {}, qint64(1) << 40, {}) << "gripCount";
        // Positions for three vertices where the sheet has more.
        const auto threePositions = [](const char* countKey, const char* key) {
            QCborMap root = QCborValue::fromCbor(validFile()).toMap();
            QCborMap sheet = root[QLatin1String("sheet")].toMap();
            sheet[QLatin1String(countKey)] = 3;
            sheet[QLatin1String(key)] = f64s({0, 0, 0, 0, 0, 0, 0, 0, 0});
            root[QLatin1String("sheet")] = sheet;
            return QCborValue(root).toCbor();
        };
        QTest::newRow("still positions for three vertices")
            << threePositions("stillFromCount", "stillFrom") << "3 positions for";
        QTest::newRow("slow still means for three vertices")
            << threePositions("slowStillMeanCount", "slowStillMean") << "3 positions for";
        QTest::newRow("a slide of negative speed")
            << withField({"sheet", "deskSlide"}, -0.5) << "slide across the desk";
        QTest::newRow("a slide faster than sound")
            << withField({"sheet", "deskSlide"}, 1e6) << "deskSlide";
        QTest::newRow("huge vertex count")
            << withField({"sheet", "vertexCount"}, qint64(1) << 40) << "vertexCount";
        QTest::newRow("count disagrees with bytes")
            << withField({"sheet", "vertexCount"}, 100) << "bytes";
        QTest::newRow("positions truncated")
            << withField({"sheet", "x"}, QByteArray(10, 'x')) << "sheet.x";
        QTest::newRow("NaN position")
            << withBytes("x", 8 * 4, QByteArray::fromHex("000000000000f87f")) << "non-finite";
        QTest::newRow("spring end out of range")
            << withBytes("springA", 4 * 5, le32(999999)) << "spring 5";
        QTest::newRow("negative triangle vertex")
            << withBytes("triangleVertices", 0, le32(-7)) << "triangle 0";
        QTest::newRow("inconsistent adjacency") << withBytes("faces", 8 * 2, le32(3)) << "spring 2";
        QTest::newRow("unknown spring kind")
            << withBytes("kind", 0, QByteArray(1, char(9))) << "kind";
        QTest::newRow("zero mass") << withBytes("m", 0, QByteArray(8, '\0')) << "mass";
        QTest::newRow("all-zero rng") << withField({"rng"}, QByteArray(32, '\0')) << "rng";
        QTest::newRow("pin out of range")
            << withField({"script", "pins"},
                         QCborArray{QCborMap{{QStringLiteral("vertices"), le32(1 << 30)}}})
            << "pins";
    }
    void brokenFilesAreRefusedWithAMessage() {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, mentions);
        const WorldLoad l = decodeWorld(bytes);
        QVERIFY(!l.world);
        QVERIFY(!l.error.isEmpty());
        QVERIFY2(!l.error.contains(QLatin1Char('\n')), qPrintable(l.error));
        QVERIFY2(l.error.contains(mentions), qPrintable(l.error));
    }

    void truncationAtEveryOffsetIsRefused() {
        const QByteArray good = validFile();
        // Every offset in the first 4 KiB (headers, small fields) and a stride after.
        int refused = 0, tried = 0;
        for (qsizetype n = 0; n < good.size(); n += (n < 4096 ? 1 : 997)) {
            ++tried;
            refused += !decodeWorld(good.left(n)).world;
        }
        QCOMPARE(refused, tried);
        // Said as what it is: a user read "Unexpected end of input data (more bytes
        // needed)" for a file cut short.
        const QByteArray halfFile = good.left(good.size() / 2);
        const QString half = decodeWorld(halfFile).error;
        QVERIFY2(half.contains(QStringLiteral("cut short")), qPrintable(half));
        QVERIFY2(half.contains(QStringLiteral("after %1 bytes").arg(halfFile.size())),
                 qPrintable(half));
        // Cut inside its first value, it is not empty.
        const QString first = decodeWorld(good.left(1)).error;
        QVERIFY2(first.contains(QStringLiteral("after 1 byte,")), qPrintable(first));
    }

    void bitFlipsNeverCrash() {
        const QByteArray good = validFile();
        Rng rng(99);
        int accepted = 0;
        for (int trial = 0; trial < 1500; ++trial) {
            QByteArray b = good;
            const int flips = 1 + static_cast<int>(rng.uniform() * 4);
            for (int k = 0; k < flips; ++k) {
                const auto at = static_cast<qsizetype>(rng.uniform() * b.size());
                b[at] = static_cast<char>(b[at] ^ (1 << static_cast<int>(rng.uniform() * 8)));
            }
            const WorldLoad l = decodeWorld(b);
            // A flip inside a position or velocity can be a valid file; then it must
            // still be a valid sheet that steps.
            if (l.world) {
                ++accepted;
                Simulation sim(*l.world);
                for (int k = 0; k < 3; ++k) sim.step();
            } else {
                QVERIFY(!l.error.isEmpty());
            }
        }
        qInfo("bit flips: %d of 1500 corrupted files still valid (flips in free numbers)",
              accepted);
    }

    void randomBytesAreRefused() {
        Rng rng(5);
        for (int trial = 0; trial < 500; ++trial) {
            QByteArray b(static_cast<qsizetype>(rng.uniform() * 4096), '\0');
            for (char& c : b) c = static_cast<char>(rng.next());
            QVERIFY(!decodeWorld(b).world);
        }
    }
};

QTEST_GUILESS_MAIN(TestSheetFile)
#include "test_sheet_file.moc"
