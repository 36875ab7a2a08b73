#include "SheetFile.h"

#include "BoundedCbor.h"
#include "Breaking.h"
#include "InputFile.h"
#include "Integrator.h"
#include "LittleEndian.h"
#include "OutputFile.h"
#include "RecordingFile.h"
#include "SheetValidation.h"

#include <QCborArray>
#include <QCborMap>
#include <QCborValue>
#include <QtEndian>
#include <cmath>

namespace pf {

namespace {

// ---------------------------------------------------------------- packing
// Bulk arrays are CBOR byte strings of little-endian numbers: exact, compact, and
// their length can be checked against the declared count before anything is built.

void putI32(QByteArray& out, std::int32_t v) {
    le::put(out, v);
}
void putI64(QByteArray& out, std::int64_t v) {
    le::put(out, v);
}
using le::putF64;
void putVec3(QByteArray& out, const Vec3& v) {
    for (int k = 0; k < 3; ++k) putF64(out, v[k]);
}

// Reads sequentially from a byte string whose size has already been checked.
// Holds its own reference to the bytes (implicitly shared, no copy), so it can
// never outlive them.
class Unpacker {
  public:
    explicit Unpacker(QByteArray b) : bytes_(std::move(b)), p_(bytes_.constData()) {}
    std::int32_t i32() {
        const auto v = le::take<std::int32_t>(p_);
        p_ += 4;
        return v;
    }
    std::int64_t i64() {
        const auto v = le::take<std::int64_t>(p_);
        p_ += 8;
        return v;
    }
    double f64() {
        const double v = le::takeF64(p_);
        p_ += 8;
        return v;
    }
    Vec3 vec3() {
        Vec3 v;
        for (int k = 0; k < 3; ++k) v[k] = f64();
        return v;
    }
    std::uint8_t u8() { return static_cast<std::uint8_t>(*p_++); }

  private:
    QByteArray bytes_;
    const char* p_;
};

constexpr qint64 kEventRecordBytes = 4 + 4 + 8 + 4 + 4 + 16 + 16 + 2 * 24 + 4 * 24 + 16;
constexpr qint64 kPlasticRecordBytes = 5 * 4 + 24;
constexpr qint64 kGripRecordBytes = 4 + 2 * 24;

void putTriangle(QByteArray& out, const Triangle& t) {
    for (Index v : t.v) putI32(out, v);
    for (Index e : t.e) putI32(out, e);
}
Triangle takeTriangle(Unpacker& u) {
    Triangle t;
    for (Index& v : t.v) v = u.i32();
    for (Index& e : t.e) e = u.i32();
    return t;
}

QByteArray packEvents(const std::vector<DamageEvent>& events) {
    QByteArray out;
    out.reserve(static_cast<qsizetype>(events.size() * kEventRecordBytes));
    for (const DamageEvent& ev : events) {
        putI32(out, static_cast<std::int32_t>(ev.kind));
        putI32(out, ev.active ? 1 : 0);
        putI64(out, ev.step);
        putI32(out, ev.edge);
        putI32(out, ev.vertex);
        for (Index s : ev.springs) putI32(out, s);
        for (Index t : ev.tris) putI32(out, t);
        for (const Triangle& t : ev.oldTris) putTriangle(out, t);
        for (const Triangle& t : ev.newTris) putTriangle(out, t);
        putF64(out, ev.massTaken[0]);
        putF64(out, ev.massTaken[1]);
    }
    return out;
}

QCborMap paramsToCbor(const SimParams& p) {
    QCborMap m;
    m[QLatin1String("phi")] = p.phi;
    m[QLatin1String("psi")] = p.psi;
    m[QLatin1String("sigma")] = p.sigma;
    m[QLatin1String("dt")] = p.dt;
    m[QLatin1String("iterations")] = p.iterations;
    m[QLatin1String("integrator")] = QString::fromStdString(p.integrator);
    QCborArray k, c;
    for (int i = 0; i < kSpringKindCount; ++i) {
        k.append(p.stiffness[i]);
        c.append(p.damping[i]);
    }
    m[QLatin1String("stiffness")] = k;
    m[QLatin1String("damping")] = c;
    m[QLatin1String("gravity")] = p.gravity;
    m[QLatin1String("gravityOutsideFilter")] = p.gravityOutsideFilter;
    m[QLatin1String("clampCompressed")] = p.clampCompressed;
    m[QLatin1String("breaking")] = p.breaking;
    m[QLatin1String("hinges")] = p.hinges;
    m[QLatin1String("selfContact")] = p.selfContact;
    m[QLatin1String("hingeThreshold")] = p.hingeThreshold;
    m[QLatin1String("breakReferenceStep")] = p.breakReferenceStep;
    m[QLatin1String("breakReferenceContraction")] = p.breakReferenceContraction;
    m[QLatin1String("groundFriction")] = p.groundFriction;
    m[QLatin1String("sphereFriction")] = p.sphereFriction;
    QCborMap mat;
    mat[QLatin1String("name")] = QString::fromStdString(p.material.name);
    mat[QLatin1String("arealDensity")] = p.material.arealDensity;
    mat[QLatin1String("stretchStiffness")] = p.material.stretchStiffness;
    mat[QLatin1String("bendingStiffness")] = p.material.bendingStiffness;
    mat[QLatin1String("yieldCurvature")] = p.material.yieldCurvature;
    mat[QLatin1String("creaseSpacing")] = p.material.creaseSpacing;
    mat[QLatin1String("groundStaticFriction")] = p.material.groundStaticFriction;
    mat[QLatin1String("groundKineticFriction")] = p.material.groundKineticFriction;
    mat[QLatin1String("toolStaticFriction")] = p.material.toolStaticFriction;
    mat[QLatin1String("toolKineticFriction")] = p.material.toolKineticFriction;
    mat[QLatin1String("thickness")] = p.material.thickness;
    mat[QLatin1String("paperStaticFriction")] = p.material.paperStaticFriction;
    mat[QLatin1String("paperKineticFriction")] = p.material.paperKineticFriction;
    m[QLatin1String("material")] = mat;
    m[QLatin1String("substeps")] = p.substeps;
    m[QLatin1String("bendingDamping")] = p.bendingDamping;
    m[QLatin1String("toolForce")] = p.toolForce;
    return m;
}

QCborMap sheetToCbor(const Sheet& s) {
    QByteArray x, v, m, X, pinned, a, b, rest, kind, breakable, hinged, faces, event, peak, tv, te;
    for (Index i = 0; i < s.verts.size(); ++i) {
        putVec3(x, s.verts.x[i]);
        putVec3(v, s.verts.v[i]);
        putF64(m, s.verts.m[i]);
        putF64(X, s.verts.X[i].x());
        putF64(X, s.verts.X[i].y());
        pinned.append(static_cast<char>(s.verts.pinned[i]));
    }
    const Springs& S = s.springs;
    for (Index i = 0; i < S.size(); ++i) {
        putI32(a, S.a[i]);
        putI32(b, S.b[i]);
        putF64(rest, S.rest[i]);
        kind.append(static_cast<char>(S.kind[i]));
        breakable.append(static_cast<char>(S.breakable[i]));
        hinged.append(static_cast<char>(S.hinged[i]));
        putI32(faces, S.faces[i][0]);
        putI32(faces, S.faces[i][1]);
        putI32(event, S.event[i]);
        putF64(peak, S.peakContraction[i]);
    }
    for (const Triangle& t : s.tris) {
        for (Index w : t.v) putI32(tv, w);
        for (Index e : t.e) putI32(te, e);
    }
    QCborMap o;
    o[QLatin1String("density")] = s.density;
    o[QLatin1String("vertexCount")] = s.verts.size();
    o[QLatin1String("springCount")] = S.size();
    o[QLatin1String("triangleCount")] = s.triangleCount();
    o[QLatin1String("eventCount")] = static_cast<qint64>(s.events.size());
    o[QLatin1String("x")] = x;
    o[QLatin1String("v")] = v;
    o[QLatin1String("m")] = m;
    o[QLatin1String("X")] = X;
    o[QLatin1String("pinned")] = pinned;
    o[QLatin1String("springA")] = a;
    o[QLatin1String("springB")] = b;
    o[QLatin1String("rest")] = rest;
    o[QLatin1String("kind")] = kind;
    o[QLatin1String("breakable")] = breakable;
    o[QLatin1String("hinged")] = hinged;
    o[QLatin1String("faces")] = faces;
    o[QLatin1String("springEvent")] = event;
    o[QLatin1String("peakContraction")] = peak;
    o[QLatin1String("triangleVertices")] = tv;
    o[QLatin1String("triangleEdges")] = te;
    o[QLatin1String("events")] = packEvents(s.events);
    // The xpbd integrator's state (optional; absent in older files: none).
    QByteArray plastic, grips;
    for (const PaperState::PlasticBend& p : s.paper.plastic) {
        for (Index v : p.vertices) putI32(plastic, v);
        putVec3(plastic, p.rest);
    }
    for (const PaperState::ToolGrip& g : s.paper.grips) {
        putI32(grips, g.triangle);
        putVec3(grips, g.barycentric);
        putVec3(grips, g.offset);
    }
    o[QLatin1String("plasticCount")] = static_cast<qint64>(s.paper.plastic.size());
    o[QLatin1String("plastic")] = plastic;
    o[QLatin1String("gripCount")] = static_cast<qint64>(s.paper.grips.size());
    o[QLatin1String("grips")] = grips;
    o[QLatin1String("quietSteps")] = s.paper.quietSteps;
    o[QLatin1String("deskSlide")] = s.paper.deskSlide;
    // Where the vertices' means were when the sheet fell still, and the means (none, or
    // one per vertex), for each average the still rule reads.
    const auto putWatch = [&](const PaperState::StillWatch& watch, const QString& prefix) {
        o[prefix + QLatin1String("Steps")] = watch.steps;
        for (const auto& [positions, name] : {std::pair{&watch.from, QLatin1String("From")},
                                              {&watch.mean, QLatin1String("Mean")}}) {
            QByteArray bytes;
            for (const Vec3& p : *positions) putVec3(bytes, p);
            o[prefix + name + QLatin1String("Count")] = static_cast<qint64>(positions->size());
            o[prefix + name] = bytes;
        }
    };
    putWatch(s.paper.still, QStringLiteral("still"));
    putWatch(s.paper.slowStill, QStringLiteral("slowStill"));
    return o;
}

// ---------------------------------------------------------------- reading

// Thrown inside the decoder only; decodeWorld turns it into WorldLoad::error.
struct FormatError {
    QString message;
};

[[noreturn]] void fail(const QString& message) {
    throw FormatError{message};
}

QCborMap mapAt(const QCborMap& m, const char* key, const QString& where) {
    const QCborValue v = m.value(QLatin1String(key));
    if (!v.isMap()) fail(QStringLiteral("%1.%2: missing or not a map").arg(where, key));
    return v.toMap();
}

double realAt(const QCborMap& m, const char* key, const QString& where, double min, double max) {
    const QCborValue v = m.value(QLatin1String(key));
    if (!v.isDouble() && !v.isInteger())
        fail(QStringLiteral("%1.%2: missing or not a number").arg(where, key));
    const double d = v.toDouble();
    if (!std::isfinite(d) || d < min || d > max)
        fail(QStringLiteral("%1.%2: %3 is outside [%4, %5]")
                 .arg(where, key)
                 .arg(d)
                 .arg(min)
                 .arg(max));
    return d;
}

qint64 integerAt(const QCborMap& m, const char* key, const QString& where, qint64 min, qint64 max) {
    const QCborValue v = m.value(QLatin1String(key));
    if (!v.isInteger()) fail(QStringLiteral("%1.%2: missing or not an integer").arg(where, key));
    const qint64 i = v.toInteger();
    if (i < min || i > max)
        fail(QStringLiteral("%1.%2: %3 is outside [%4, %5]")
                 .arg(where, key)
                 .arg(i)
                 .arg(min)
                 .arg(max));
    return i;
}

bool boolAt(const QCborMap& m, const char* key, const QString& where) {
    const QCborValue v = m.value(QLatin1String(key));
    if (!v.isBool()) fail(QStringLiteral("%1.%2: missing or not a boolean").arg(where, key));
    return v.toBool();
}

QString textAt(const QCborMap& m, const char* key, const QString& where, qsizetype maxLength) {
    const QCborValue v = m.value(QLatin1String(key));
    if (!v.isString()) fail(QStringLiteral("%1.%2: missing or not text").arg(where, key));
    const QString s = v.toString();
    if (s.size() > maxLength) fail(QStringLiteral("%1.%2: text too long").arg(where, key));
    // Names, which the commands print and the editor shows: a scene named "\n\x1b[31m"
    // was printed raw to the terminal.
    for (QChar c : s)
        if (c.category() == QChar::Other_Control)
            fail(QStringLiteral("%1.%2: a control character (U+%3) in the text")
                     .arg(where, key)
                     .arg(c.unicode(), 4, 16, QLatin1Char('0')));
    return s;
}

// A byte string of exactly count * elementBytes bytes.
QByteArray bytesAt(const QCborMap& m, const char* key, const QString& where, qint64 count,
                   qint64 elementBytes) {
    const QCborValue v = m.value(QLatin1String(key));
    if (!v.isByteArray())
        fail(QStringLiteral("%1.%2: missing or not a byte string").arg(where, key));
    const QByteArray b = v.toByteArray();
    if (b.size() != count * elementBytes)
        fail(QStringLiteral("%1.%2: %3 bytes where %4 elements need %5")
                 .arg(where, key)
                 .arg(b.size())
                 .arg(count)
                 .arg(count * elementBytes));
    return b;
}

SimParams paramsFromCbor(const QCborMap& m) {
    const QString w = QStringLiteral("params");
    SimParams p;
    p.phi = realAt(m, "phi", w, 0.0, 1.0);
    p.psi = realAt(m, "psi", w, 0.0, 1.0);
    p.sigma = realAt(m, "sigma", w, 0.0, 4.0);
    p.dt = realAt(m, "dt", w, 1e-7, 0.1);
    p.iterations = static_cast<int>(integerAt(m, "iterations", w, 0, 1000));
    p.integrator = textAt(m, "integrator", w, 64).toStdString();
    if (!makeIntegrator(p.integrator))
        fail(QStringLiteral("params.integrator: unknown integrator '%1'")
                 .arg(QString::fromStdString(p.integrator)));
    for (const char* key : {"stiffness", "damping"}) {
        const QCborValue v = m.value(QLatin1String(key));
        if (!v.isArray() || v.toArray().size() != kSpringKindCount)
            fail(QStringLiteral("params.%1: not an array of %2 numbers")
                     .arg(key)
                     .arg(kSpringKindCount));
        const QCborArray arr = v.toArray();
        for (int i = 0; i < kSpringKindCount; ++i) {
            const double d = arr.at(i).toDouble(-1.0);
            if (!(arr.at(i).isDouble() || arr.at(i).isInteger()) || !std::isfinite(d) || d < 0.0 ||
                d > 1e9)
                fail(QStringLiteral("params.%1[%2]: not a number in [0, 1e9]").arg(key).arg(i));
            (key[0] == 's' ? p.stiffness : p.damping)[i] = d;
        }
    }
    p.gravity = realAt(m, "gravity", w, -1e3, 1e3);
    p.gravityOutsideFilter = boolAt(m, "gravityOutsideFilter", w);
    p.clampCompressed = boolAt(m, "clampCompressed", w);
    p.breaking = boolAt(m, "breaking", w);
    p.hinges = boolAt(m, "hinges", w);
    // Files from before self-contact: their sheet goes on with it, as new ones do.
    if (m.contains(QLatin1String("selfContact"))) p.selfContact = boolAt(m, "selfContact", w);
    p.hingeThreshold = realAt(m, "hingeThreshold", w, 0.0, 10.0);
    p.breakReferenceStep = realAt(m, "breakReferenceStep", w, 1e-6, 10.0);
    // Absent from files written while Eq. 10 was read per unit of time: the default.
    if (m.contains(QLatin1String("breakReferenceContraction")))
        p.breakReferenceContraction = realAt(m, "breakReferenceContraction", w, 1e-9, 1.0);
    p.groundFriction = realAt(m, "groundFriction", w, 0.0, 1.0);
    p.sphereFriction = realAt(m, "sphereFriction", w, 0.0, 1.0);
    // The material and the xpbd settings came after the first files were written:
    // a file without them has office paper and the defaults.
    if (m.contains(QLatin1String("material"))) {
        const QString wm = QStringLiteral("params.material");
        const QCborMap mat = mapAt(m, "material", w);
        Material& x = p.material;
        x.name = textAt(mat, "name", wm, 64).toStdString();
        x.arealDensity = realAt(mat, "arealDensity", wm, 1e-4, 10.0);
        x.stretchStiffness = realAt(mat, "stretchStiffness", wm, 1.0, 1e9);
        x.bendingStiffness = realAt(mat, "bendingStiffness", wm, 1e-9, 10.0);
        // Files from before plastic bending keep their preset's yield.
        if (mat.contains(QLatin1String("yieldCurvature")))
            x.yieldCurvature = realAt(mat, "yieldCurvature", wm, 1e-3, 1e6);
        else if (Material preset; materialPreset(x.name, preset))
            x.yieldCurvature = preset.yieldCurvature;
        if (mat.contains(QLatin1String("creaseSpacing")))
            x.creaseSpacing = realAt(mat, "creaseSpacing", wm, 0.0, 1.0);
        else if (Material preset; materialPreset(x.name, preset))
            x.creaseSpacing = preset.creaseSpacing;
        x.groundStaticFriction = realAt(mat, "groundStaticFriction", wm, 0.0, 10.0);
        x.groundKineticFriction = realAt(mat, "groundKineticFriction", wm, 0.0, 10.0);
        x.toolStaticFriction = realAt(mat, "toolStaticFriction", wm, 0.0, 10.0);
        x.toolKineticFriction = realAt(mat, "toolKineticFriction", wm, 0.0, 10.0);
        // Files from before self-contact take their preset's thickness and friction.
        if (mat.contains(QLatin1String("thickness"))) {
            x.thickness = realAt(mat, "thickness", wm, 0.0, 0.1);
            x.paperStaticFriction = realAt(mat, "paperStaticFriction", wm, 0.0, 10.0);
            x.paperKineticFriction = realAt(mat, "paperKineticFriction", wm, 0.0, 10.0);
        } else if (Material preset; materialPreset(x.name, preset)) {
            x.thickness = preset.thickness;
            x.paperStaticFriction = preset.paperStaticFriction;
            x.paperKineticFriction = preset.paperKineticFriction;
        }
    }
    if (m.contains(QLatin1String("substeps")))
        p.substeps = static_cast<int>(integerAt(m, "substeps", w, 1, 1000));
    if (m.contains(QLatin1String("bendingDamping")))
        p.bendingDamping = realAt(m, "bendingDamping", w, 0.0, 10.0);
    if (m.contains(QLatin1String("toolForce")))
        p.toolForce = realAt(m, "toolForce", w, 0.0, 1000.0);
    return p;
}

// Positions under `key`, as many as `countKey` says: none, or one per vertex.
std::vector<Vec3> noneOrOnePerVertex(const QCborMap& m, const char* countKey, const char* key,
                                     const QString& where, qint64 vertices) {
    const qint64 n = integerAt(m, countKey, where, 0, vertices);
    if (n != 0 && n != vertices)
        fail(QStringLiteral("%1.%2: %3 positions for %4 vertices")
                 .arg(where, QLatin1String(countKey))
                 .arg(n)
                 .arg(vertices));
    Unpacker u(bytesAt(m, key, where, n, 24));
    std::vector<Vec3> positions(static_cast<std::size_t>(n));
    for (Vec3& p : positions) p = u.vec3();
    return positions;
}

Sheet sheetFromCbor(const QCborMap& m) {
    const QString w = QStringLiteral("sheet");
    Sheet s;
    s.density = realAt(m, "density", w, 1e-9, 1e9);
    const qint64 nv = integerAt(m, "vertexCount", w, 3, kMaxFileVertices);
    const qint64 ns = integerAt(m, "springCount", w, 3, kMaxFileSprings);
    const qint64 nt = integerAt(m, "triangleCount", w, 1, kMaxFileTriangles);
    const qint64 ne = integerAt(m, "eventCount", w, 0, kMaxFileEvents);

    // Every size is checked before any array is filled.
    const QByteArray x = bytesAt(m, "x", w, nv, 24), v = bytesAt(m, "v", w, nv, 24);
    const QByteArray mass = bytesAt(m, "m", w, nv, 8), X = bytesAt(m, "X", w, nv, 16);
    const QByteArray pinned = bytesAt(m, "pinned", w, nv, 1);
    const QByteArray a = bytesAt(m, "springA", w, ns, 4), b = bytesAt(m, "springB", w, ns, 4);
    const QByteArray rest = bytesAt(m, "rest", w, ns, 8), kind = bytesAt(m, "kind", w, ns, 1);
    const QByteArray breakable = bytesAt(m, "breakable", w, ns, 1);
    const QByteArray hinged = bytesAt(m, "hinged", w, ns, 1);
    const QByteArray faces = bytesAt(m, "faces", w, ns, 8);
    const QByteArray event = bytesAt(m, "springEvent", w, ns, 4);
    const QByteArray tv = bytesAt(m, "triangleVertices", w, nt, 12);
    const QByteArray te = bytesAt(m, "triangleEdges", w, nt, 12);
    const QByteArray events = bytesAt(m, "events", w, ne, kEventRecordBytes);

    Unpacker ux(x), uv(v), um(mass), uX(X), up(pinned);
    for (qint64 i = 0; i < nv; ++i) {
        const Vec3 p = ux.vec3(), vel = uv.vec3();
        const double mi = um.f64();
        const double X0 = uX.f64(), X1 = uX.f64();
        const Index id = s.addVertex(p, vel, mi, Vec2(X0, X1));
        s.verts.pinned[id] = up.u8();
    }
    Unpacker ua(a), ub(b), ur(rest), uk(kind), ubr(breakable), uh(hinged), uf(faces), ue(event);
    for (qint64 i = 0; i < ns; ++i) {
        const Index sa = ua.i32(), sb = ub.i32();
        const double r = ur.f64();
        const std::uint8_t k = uk.u8();
        if (k >= kSpringKindCount)
            fail(QStringLiteral("sheet.kind[%1]: unknown spring kind %2").arg(i).arg(k));
        const Index id = s.addSpring(sa, sb, r, static_cast<SpringKind>(k), false);
        s.springs.breakable[id] = ubr.u8();
        s.springs.hinged[id] = uh.u8();
        s.springs.faces[id][0] = uf.i32();
        s.springs.faces[id][1] = uf.i32();
        s.springs.event[id] = ue.i32();
    }
    Unpacker utv(tv), ute(te);
    s.tris.resize(static_cast<std::size_t>(nt));
    for (Triangle& t : s.tris) {
        for (Index& id : t.v) id = utv.i32();
        for (Index& id : t.e) id = ute.i32();
    }
    Unpacker uev(events);
    s.events.resize(static_cast<std::size_t>(ne));
    for (DamageEvent& ev : s.events) {
        const std::int32_t k = uev.i32(), active = uev.i32();
        if (k != 0 && k != 1) fail(QStringLiteral("sheet.events: unknown event kind %1").arg(k));
        if (active != 0 && active != 1) fail(QStringLiteral("sheet.events: invalid active flag"));
        ev.kind = static_cast<EventKind>(k);
        ev.active = active == 1;
        ev.step = uev.i64();
        ev.edge = uev.i32();
        ev.vertex = uev.i32();
        for (Index& id : ev.springs) id = uev.i32();
        for (Index& id : ev.tris) id = uev.i32();
        for (Triangle& t : ev.oldTris) t = takeTriangle(uev);
        for (Triangle& t : ev.newTris) t = takeTriangle(uev);
        ev.massTaken[0] = uev.f64();
        ev.massTaken[1] = uev.f64();
    }
    if (m.contains(QLatin1String("plasticCount"))) {
        // A stencil per grid direction and one per edge at most.
        const qint64 np = integerAt(m, "plasticCount", w, 0, 4 * nv + ns);
        Unpacker u(bytesAt(m, "plastic", w, np, kPlasticRecordBytes));
        s.paper.plastic.resize(static_cast<std::size_t>(np));
        for (PaperState::PlasticBend& p : s.paper.plastic) {
            for (Index& v : p.vertices) v = u.i32();
            p.rest = u.vec3();
        }
        const qint64 ng = integerAt(m, "gripCount", w, 0, nt);
        Unpacker ug(bytesAt(m, "grips", w, ng, kGripRecordBytes));
        s.paper.grips.resize(static_cast<std::size_t>(ng));
        for (PaperState::ToolGrip& g : s.paper.grips) {
            g.triangle = ug.i32();
            g.barycentric = ug.vec3();
            g.offset = ug.vec3();
        }
        s.paper.quietSteps = static_cast<int>(integerAt(m, "quietSteps", w, 0, 1'000'000'000));
    }
    // Absent in files from before it: the sheet falls still from its first step on.
    if (m.contains(QLatin1String("stillFromCount"))) {
        s.paper.still.steps = static_cast<int>(integerAt(m, "stillSteps", w, 0, 1'000'000'000));
        s.paper.still.from = noneOrOnePerVertex(m, "stillFromCount", "stillFrom", w, nv);
        s.paper.deskSlide = realAt(m, "deskSlide", w, -1.0, 1e3);
    }
    // Absent in files from before it: the mean starts again from where the sheet is.
    if (m.contains(QLatin1String("stillMeanCount")))
        s.paper.still.mean = noneOrOnePerVertex(m, "stillMeanCount", "stillMean", w, nv);
    // Absent in files from before the slow average: it starts again from where the sheet is.
    if (m.contains(QLatin1String("slowStillFromCount"))) {
        s.paper.slowStill.steps =
            static_cast<int>(integerAt(m, "slowStillSteps", w, 0, 1'000'000'000));
        s.paper.slowStill.from =
            noneOrOnePerVertex(m, "slowStillFromCount", "slowStillFrom", w, nv);
        s.paper.slowStill.mean =
            noneOrOnePerVertex(m, "slowStillMeanCount", "slowStillMean", w, nv);
    }
    // Files from before load-driven breaking hold no peaks: the sheet counts as having
    // carried the load it stands under, so loading it does not set off a burst of breaks.
    const bool hasPeaks = m.contains(QLatin1String("peakContraction"));
    if (hasPeaks) {
        Unpacker u(bytesAt(m, "peakContraction", w, ns, 8));
        for (double& peak : s.springs.peakContraction) peak = u.f64();
    }
    const std::string problem = validateSheet(s);
    if (!problem.empty()) fail(QStringLiteral("sheet: %1").arg(QString::fromStdString(problem)));
    // The chord, as every integrator read it when files held no peaks (jacobi's
    // reading; the default xpbd reads the arc).
    if (!hasPeaks) {
        SimParams chord;
        chord.integrator = "jacobi";
        recordCurrentContraction(s, chord);
    }
    return s;
}

std::uint64_t u64From(const QByteArray& b, qsizetype offset) {
    return le::take<std::uint64_t>(b.constData() + offset);
}

World worldFromCbor(const QCborMap& root) {
    const QString w = QStringLiteral("file");
    const QString magic = textAt(root, "magic", w, 64);
    if (magic == QLatin1String(kRecordingMagic))
        fail(QStringLiteral("a PaperFold recording, not a sheet: `paperfold replay` plays it "
                            "(its --save writes the sheet it ends with)"));
    if (magic != QLatin1String(kSheetFileMagic))
        fail(QStringLiteral("not a PaperFold sheet (wrong magic)"));
    const qint64 version = integerAt(root, "version", w, 0, 1'000'000);
    if (version != kSheetFileVersion)
        fail(QStringLiteral("unsupported sheet file version %1 (this build reads version %2)")
                 .arg(version)
                 .arg(kSheetFileVersion));

    World world;
    world.scene = textAt(root, "scene", w, 256).toStdString();
    world.seed = u64From(bytesAt(root, "seed", w, 1, 8), 0);
    const QByteArray rng = bytesAt(root, "rng", w, 4, 8);
    Rng::State state;
    for (int k = 0; k < 4; ++k) state[k] = u64From(rng, 8 * k);
    if (!world.rng.setState(state)) fail(QStringLiteral("file.rng: the all-zero state is invalid"));
    world.time = realAt(root, "time", w, 0.0, 1e12);
    // Far more steps than any session takes (a million years at 240 a second), and far
    // enough from the largest integer that stepping on never overflows (a file at
    // 2⁶³ − 1 was stepped to -2⁶³ + 2 and then refused its own save).
    constexpr qint64 kLargestStep = qint64(1) << 53;
    world.stepCount = integerAt(root, "step", w, 0, kLargestStep);
    world.params = paramsFromCbor(mapAt(root, "params", w));

    const QCborMap sphere = mapAt(root, "sphere", w);
    const QString ws = QStringLiteral("sphere");
    Unpacker uc(bytesAt(sphere, "center", ws, 1, 24)), uv(bytesAt(sphere, "velocity", ws, 1, 24));
    world.sphere.center = uc.vec3();
    world.sphere.velocity = uv.vec3();
    if (!world.sphere.center.allFinite() || !world.sphere.velocity.allFinite())
        fail(QStringLiteral("sphere: non-finite position or velocity"));
    world.sphere.radius = realAt(sphere, "radius", ws, 1e-6, 100.0);
    world.sphere.active = boolAt(sphere, "active", ws);
    // Files from before the editor's tool hovered have no such key.
    if (sphere.contains(QLatin1String("hovering")))
        world.sphere.hovering = boolAt(sphere, "hovering", ws);

    const QCborMap ground = mapAt(root, "ground", w);
    world.groundEnabled = boolAt(ground, "enabled", QStringLiteral("ground"));
    world.groundHeight = realAt(ground, "height", QStringLiteral("ground"), -1e3, 1e3);

    world.sheet = sheetFromCbor(mapAt(root, "sheet", w));
    const Index nv = world.sheet.verts.size();

    const QCborMap script = mapAt(root, "script", w);
    const QString wsc = QStringLiteral("script");
    const QCborValue keysValue = script.value(QLatin1String("sphereKeys"));
    if (!keysValue.isByteArray() || keysValue.toByteArray().size() % 32 != 0 ||
        keysValue.toByteArray().size() > 32 * 100000)
        fail(QStringLiteral("script.sphereKeys: not a byte string of (t, x, y, z) records"));
    const QByteArray keys = keysValue.toByteArray();
    Unpacker uk(keys);
    double lastTime = -std::numeric_limits<double>::infinity();
    for (qsizetype k = 0; k < keys.size() / 32; ++k) {
        SphereKey key;
        key.time = uk.f64();
        key.center = uk.vec3();
        if (!std::isfinite(key.time) || !key.center.allFinite() || key.time < lastTime)
            fail(QStringLiteral("script.sphereKeys[%1]: non-finite or out of order").arg(k));
        lastTime = key.time;
        world.script.sphereKeys.push_back(key);
    }
    const QCborValue pins = script.value(QLatin1String("pins"));
    if (!pins.isArray() || pins.toArray().size() > 1000)
        fail(QStringLiteral("script.pins: not an array of at most 1000 groups"));
    for (const QCborValue& g : pins.toArray()) {
        if (!g.isMap()) fail(QStringLiteral("script.pins: a group is not a map"));
        const QCborMap gm = g.toMap();
        const QCborValue ids = gm.value(QLatin1String("vertices"));
        if (!ids.isByteArray() || ids.toByteArray().size() % 4 != 0 ||
            ids.toByteArray().size() / 4 > nv)
            fail(QStringLiteral("script.pins.vertices: not a byte string of vertex ids"));
        PinGroup group;
        const QByteArray idBytes = ids.toByteArray();
        Unpacker ui(idBytes);
        for (qsizetype k = 0; k < idBytes.size() / 4; ++k) {
            const Index id = ui.i32();
            if (id < 0 || id >= nv)
                fail(QStringLiteral("script.pins.vertices: vertex %1 out of range").arg(id));
            group.vertices.push_back(id);
        }
        Unpacker uvel(bytesAt(gm, "velocity", wsc, 1, 24));
        group.velocity = uvel.vec3();
        if (!group.velocity.allFinite()) fail(QStringLiteral("script.pins.velocity: not finite"));
        group.until = realAt(gm, "until", wsc, -1e12, 1e12);
        // Turning, scaling and letting go came later: a group without them only translates.
        const bool turns = gm.contains(QLatin1String("turnRate"));
        const bool scales = gm.contains(QLatin1String("scaleRate"));
        if (turns) {
            group.turnRate = realAt(gm, "turnRate", wsc, -1e3, 1e3);
            Unpacker ua(bytesAt(gm, "axis", wsc, 1, 24));
            group.axis = ua.vec3();
            if (!(std::abs(group.axis.norm() - 1.0) < 1e-9))
                fail(QStringLiteral("script.pins.axis: not a unit vector"));
        }
        if (scales) group.scaleRate = realAt(gm, "scaleRate", wsc, -100.0, 100.0);
        if (turns || scales) {
            Unpacker up(bytesAt(gm, "pivot", wsc, 1, 24));
            group.pivot = up.vec3();
            if (!group.pivot.allFinite() || group.pivot.cwiseAbs().maxCoeff() > 1e4)
                fail(QStringLiteral("script.pins.pivot: not a point within 10 km"));
        }
        if (gm.contains(QLatin1String("release")))
            group.release = realAt(gm, "release", wsc, -1e12, 1e12);
        if (gm.contains(QLatin1String("start")))
            group.start = realAt(gm, "start", wsc, -1e12, 1e12);
        world.script.pins.push_back(std::move(group));
    }
    return world;
}

// Every key the format uses, at any level: the loader builds nothing else.
const CborBounds& sheetFileBounds() {
    static const CborBounds bounds = [] {
        CborBounds b;
        for (const char* key : {"magic",
                                "version",
                                "scene",
                                "seed",
                                "rng",
                                "time",
                                "step",
                                "params",
                                "phi",
                                "psi",
                                "sigma",
                                "dt",
                                "iterations",
                                "integrator",
                                "stiffness",
                                "damping",
                                "gravity",
                                "gravityOutsideFilter",
                                "clampCompressed",
                                "breaking",
                                "hinges",
                                "hingeThreshold",
                                "breakReferenceStep",
                                "breakReferenceContraction",
                                "groundFriction",
                                "sphereFriction",
                                "material",
                                "name",
                                "arealDensity",
                                "stretchStiffness",
                                "bendingStiffness",
                                "yieldCurvature",
                                "creaseSpacing",
                                "groundStaticFriction",
                                "groundKineticFriction",
                                "toolStaticFriction",
                                "toolKineticFriction",
                                "thickness",
                                "paperStaticFriction",
                                "paperKineticFriction",
                                "selfContact",
                                "substeps",
                                "bendingDamping",
                                "toolForce",
                                "sphere",
                                "center",
                                "velocity",
                                "radius",
                                "active",
                                "hovering",
                                "ground",
                                "enabled",
                                "height",
                                "script",
                                "sphereKeys",
                                "pins",
                                "vertices",
                                "until",
                                "turnRate",
                                "scaleRate",
                                "pivot",
                                "axis",
                                "release",
                                "start",
                                "sheet",
                                "density",
                                "vertexCount",
                                "springCount",
                                "triangleCount",
                                "eventCount",
                                "x",
                                "v",
                                "m",
                                "X",
                                "pinned",
                                "springA",
                                "springB",
                                "rest",
                                "kind",
                                "breakable",
                                "hinged",
                                "faces",
                                "springEvent",
                                "peakContraction",
                                "triangleVertices",
                                "triangleEdges",
                                "events",
                                "plasticCount",
                                "plastic",
                                "gripCount",
                                "grips",
                                "quietSteps",
                                "stillSteps",
                                "stillFromCount",
                                "stillFrom",
                                "stillMeanCount",
                                "stillMean",
                                "slowStillSteps",
                                "slowStillFromCount",
                                "slowStillFrom",
                                "slowStillMeanCount",
                                "slowStillMean",
                                "deskSlide"})
            b.knownKeys.insert(QString::fromLatin1(key));
        // The deepest path is root → script → pins → group → value; at most 1000 pin
        // groups of seven entries make the most values a valid file holds.
        b.maxDepth = 6;
        b.maxValues = 20000;
        return b;
    }();
    return bounds;
}

} // namespace

QByteArray encodeWorld(const World& world) {
    QCborMap root;
    root[QLatin1String("magic")] = QLatin1String(kSheetFileMagic);
    root[QLatin1String("version")] = kSheetFileVersion;
    root[QLatin1String("scene")] = QString::fromStdString(world.scene);
    QByteArray seed, rng;
    putI64(seed, static_cast<std::int64_t>(world.seed));
    for (std::uint64_t word : world.rng.state()) putI64(rng, static_cast<std::int64_t>(word));
    root[QLatin1String("seed")] = seed;
    root[QLatin1String("rng")] = rng;
    root[QLatin1String("time")] = world.time;
    root[QLatin1String("step")] = static_cast<qint64>(world.stepCount);
    root[QLatin1String("params")] = paramsToCbor(world.params);

    QCborMap sphere;
    QByteArray center, velocity;
    putVec3(center, world.sphere.center);
    putVec3(velocity, world.sphere.velocity);
    sphere[QLatin1String("center")] = center;
    sphere[QLatin1String("velocity")] = velocity;
    sphere[QLatin1String("radius")] = world.sphere.radius;
    sphere[QLatin1String("active")] = world.sphere.active;
    sphere[QLatin1String("hovering")] = world.sphere.hovering;
    root[QLatin1String("sphere")] = sphere;

    QCborMap ground;
    ground[QLatin1String("enabled")] = world.groundEnabled;
    ground[QLatin1String("height")] = world.groundHeight;
    root[QLatin1String("ground")] = ground;

    QCborMap script;
    QByteArray keys;
    for (const SphereKey& k : world.script.sphereKeys) {
        putF64(keys, k.time);
        putVec3(keys, k.center);
    }
    script[QLatin1String("sphereKeys")] = keys;
    QCborArray pins;
    for (const PinGroup& g : world.script.pins) {
        QCborMap gm;
        QByteArray ids, vel;
        for (Index i : g.vertices) putI32(ids, i);
        putVec3(vel, g.velocity);
        gm[QLatin1String("vertices")] = ids;
        gm[QLatin1String("velocity")] = vel;
        gm[QLatin1String("until")] = g.until;
        if (g.turnRate != 0.0) {
            QByteArray axis;
            putVec3(axis, g.axis);
            gm[QLatin1String("turnRate")] = g.turnRate;
            gm[QLatin1String("axis")] = axis;
        }
        if (g.scaleRate != 0.0) gm[QLatin1String("scaleRate")] = g.scaleRate;
        if (g.turnRate != 0.0 || g.scaleRate != 0.0) {
            QByteArray pivot;
            putVec3(pivot, g.pivot);
            gm[QLatin1String("pivot")] = pivot;
        }
        if (std::isfinite(g.release)) gm[QLatin1String("release")] = g.release;
        if (std::isfinite(g.start)) gm[QLatin1String("start")] = g.start;
        pins.append(gm);
    }
    script[QLatin1String("pins")] = pins;
    root[QLatin1String("script")] = script;
    root[QLatin1String("sheet")] = sheetToCbor(world.sheet);
    return root.toCborValue().toCbor();
}

QByteArray encodeParams(const SimParams& params) {
    return QCborValue(paramsToCbor(params)).toCbor();
}

std::optional<SimParams> decodeParams(const QByteArray& bytes, QString* error) {
    const std::optional<QCborValue> root = parseBoundedCbor(bytes, sheetFileBounds(), error);
    if (!root) return std::nullopt;
    if (!root->isMap()) {
        *error = QStringLiteral("params: not a map");
        return std::nullopt;
    }
    try {
        return paramsFromCbor(root->toMap());
    } catch (const FormatError& e) {
        *error = e.message;
        return std::nullopt;
    }
}

WorldLoad decodeWorld(const QByteArray& bytes) {
    // Every sheet begins with a map (its first key the magic): a file that begins with
    // anything else is another kind of file, not a broken sheet. A text file read "the
    // file ends after 3 bytes, ... cut short", a picture "not a valid CBOR file at byte
    // 23", another "no top-level map".
    constexpr unsigned kCborMap = 5; // major type, the first byte's top three bits
    if (!bytes.isEmpty() && (static_cast<unsigned char>(bytes[0]) >> 5) != kCborMap)
        return {std::nullopt, QStringLiteral("not a PaperFold sheet: a sheet begins otherwise "
                                             "(is it another kind of file?)")};
    QString error;
    const std::optional<QCborValue> root = parseBoundedCbor(bytes, sheetFileBounds(), &error);
    if (!root) return {std::nullopt, error};
    if (!root->isMap()) // the first byte said map; kept should that check ever change
        return {std::nullopt, QStringLiteral("not a PaperFold sheet (no top-level map)")};
    try {
        return {worldFromCbor(root->toMap()), {}};
    } catch (const FormatError& e) {
        return {std::nullopt, e.message};
    }
}

bool saveWorld(const World& world, const QString& path, QString* error, const QStringList& inputs) {
    return writeOutputFile(path, encodeWorld(world), error, inputs);
}

WorldLoad loadWorld(const QString& path) {
    QString error;
    const std::optional<QByteArray> bytes = readInputFile(path, kMaxSheetFileBytes, &error);
    if (!bytes) return {std::nullopt, error};
    WorldLoad load = decodeWorld(*bytes);
    if (!load.world) load.error = QStringLiteral("%1: %2").arg(path, load.error);
    return load;
}

} // namespace pf
