#include "Fidelity.h"

#include "CLocaleNumber.h"
#include "Scenes.h"
#include "SheetBuilder.h"
#include "SheetStats.h"
#include "Simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pf {

namespace {

constexpr double kPi = std::numbers::pi;

// An angle in radians as degrees to two decimals, in the C locale ("19.32").
std::string degrees(double radians) {
    return cLocaleNumber(radians * 180.0 / kPi, std::chars_format::fixed, 2);
}

void applySolver(SimParams& p, const FidelityOptions& o) {
    p.integrator = o.integrator;
    if (o.substeps > 0) p.substeps = o.substeps;
    if (o.gravityOutsideFilter) p.gravityOutsideFilter = true;
    p.selfContact = o.selfContact;
}

World configured(World w, const FidelityOptions& o) {
    applySolver(w.params, o);
    setMaterial(w, o.material);
    return w;
}

Vec3 momentum(const Sheet& s) {
    Vec3 p = Vec3::Zero();
    for (Index i = 0; i < s.verts.size(); ++i) p += s.verts.m[i] * s.verts.v[i];
    return p;
}

double kineticEnergy(const Sheet& s) {
    double e = 0.0;
    for (Index i = 0; i < s.verts.size(); ++i) e += 0.5 * s.verts.m[i] * s.verts.v[i].squaredNorm();
    return e;
}

double maxSpeed(const Sheet& s) {
    double v2 = 0.0;
    for (const Vec3& v : s.verts.v) v2 = std::max(v2, v.squaredNorm());
    return std::sqrt(v2);
}

int stepsFor(const World& w, double seconds) {
    return static_cast<int>(std::lround(seconds / w.params.dt));
}

struct StretchRun {
    double maxStretch = 0.0, maxRms = 0.0;
    void add(const SheetStats& st) {
        maxStretch = std::max(maxStretch, st.maxStretch);
        maxRms = std::max(maxRms, st.rmsStretch);
    }
    // A run whose step blew up fails its rows rather than ending them at what came
    // before, which could pass.
    void blewUp() { maxStretch = maxRms = std::numeric_limits<double>::infinity(); }
};

void addStretchRows(std::vector<FidelityRow>& rows, const std::string& scene, const StretchRun& r) {
    rows.push_back({"stretch " + scene, "max over time of max(l/l0 - 1, 0)", 100.0 * r.maxStretch,
                    1.0, true, "%"});
    rows.push_back(
        {"stretch " + scene, "max over time of RMS stretch", 100.0 * r.maxRms, 0.1, true, "%"});
}

// press: stretch, contact with the desk and the tool, and rest after the tool left.
void pressChecks(const FidelityOptions& o, std::vector<FidelityRow>& rows) {
    Simulation sim(configured(*makeScene("press"), o));
    const World& w = sim.world();
    const double leaves = w.script.sphereKeys.back().time;
    const double end = o.quick ? leaves + 1.5 : leaves + 3.0;
    StretchRun stretch;
    double comMax = -1e9, inside = 0.0, below = 0.0, settled = -1.0;
    const double radius = w.sphere.radius;
    const int steps = stepsFor(w, end);
    for (int k = 0; k < steps; ++k) {
        if (sim.step() != StepStatus::Ok) {
            stretch.blewUp();
            settled = -1.0;
            break;
        }
        const Sheet& s = sim.world().sheet;
        stretch.add(computeStats(s));
        double m = 0.0, my = 0.0;
        for (Index i = 0; i < s.verts.size(); ++i) {
            m += s.verts.m[i];
            my += s.verts.m[i] * s.verts.x[i].y();
            below = std::max(below, w.groundHeight - s.verts.x[i].y());
            if (sim.world().sphere.active)
                inside =
                    std::max(inside, radius - (s.verts.x[i] - sim.world().sphere.center).norm());
        }
        comMax = std::max(comMax, my / m);
        const double t = sim.world().time;
        const bool quiet = kineticEnergy(s) < 1e-9 && maxSpeed(s) < 1e-3;
        if (t > leaves) {
            if (!quiet)
                settled = -1.0;
            else if (settled < 0.0)
                settled = t - leaves;
        }
    }
    addStretchRows(rows, "press", stretch);
    rows.push_back({"press contact", "highest centre of mass", 100.0 * comMax, 2.0, true, "cm"});
    rows.push_back({"press contact", "deepest vertex inside the sphere after a step",
                    1000.0 * inside, 1e-6, true, "mm"});
    rows.push_back({"press contact", "deepest vertex below the desk after a step", 1000.0 * below,
                    1e-6, true, "mm"});
    rows.push_back({"rest", "time after the tool left until KE < 1e-9 J and v < 1 mm/s for good",
                    settled < 0.0 ? 1e9 : settled, 1.0, true, "s"});
}

void stretchCheck(const FidelityOptions& o, const std::string& scene, double seconds,
                  std::vector<FidelityRow>& rows) {
    Simulation sim(configured(*makeScene(scene), o));
    StretchRun r;
    const int steps = stepsFor(sim.world(), seconds);
    for (int k = 0; k < steps; ++k) {
        if (sim.step() != StepStatus::Ok) {
            r.blewUp();
            break;
        }
        r.add(computeStats(sim.world().sheet));
    }
    addStretchRows(rows, scene, r);
}

// A sheet in the air, no desk, no tool: the centre of mass must fall at g whatever
// the sheet's shape, because internal forces cancel.
void freeFallCheck(const FidelityOptions& o, const std::string& orientation,
                   std::vector<FidelityRow>& rows) {
    World w = configured(*makeScene("drop"), o);
    w.groundEnabled = false;
    w.sphere.active = false;
    w.script = {};
    Sheet& s = w.sheet;
    Rng rng(7);
    for (Index i = 0; i < s.verts.size(); ++i) {
        const Vec2 X = s.verts.X[i];
        Vec3& x = s.verts.x[i];
        if (orientation == "flat") x = Vec3(X.x(), 1.0, X.y());
        if (orientation == "tilted 45°")
            x = Vec3(X.x(), 1.0 + X.y() * std::sin(kPi / 4), X.y() * std::cos(kPi / 4));
        if (orientation == "hanging") x = Vec3(X.x(), 1.0 + X.y(), 0.0);
        if (orientation == "crumpled")
            x = Vec3(X.x(), 1.0 + 0.02 * (rng.uniform() - 0.5), X.y()) * 0.8;
    }
    Simulation sim(w);
    const double mass = totalMass(sim.world().sheet);
    const Vec3 p0 = momentum(sim.world().sheet);
    const int steps = stepsFor(w, 0.5);
    for (int k = 0; k < steps && sim.step() == StepStatus::Ok; ++k) {
    }
    const Vec3 a = (momentum(sim.world().sheet) - p0) / (mass * sim.world().time);
    rows.push_back({"free fall " + orientation, "centre-of-mass acceleration / g, deviation",
                    100.0 * std::abs(-a.y() / w.params.gravity - 1.0), 1.0, true, "%"});
}

void momentumCheck(const FidelityOptions& o, std::vector<FidelityRow>& rows) {
    World w = configured(*makeScene("drop"), o);
    w.groundEnabled = false;
    w.params.gravity = 0.0;
    w.params.breaking = false;
    Sheet& s = w.sheet;
    const Vec3 com = centreOfMass(s);
    const Vec3 v0(1.0, 0.5, 0.2), omega(0.0, 3.0, 1.0);
    for (Index i = 0; i < s.verts.size(); ++i) s.verts.v[i] = v0 + omega.cross(s.verts.x[i] - com);
    Simulation sim(w);
    const Vec3 p0 = momentum(sim.world().sheet);
    const int steps = stepsFor(w, 1.0);
    for (int k = 0; k < steps && sim.step() == StepStatus::Ok; ++k) {
    }
    const double drift = (momentum(sim.world().sheet) - p0).norm() / p0.norm() / sim.world().time;
    rows.push_back(
        {"momentum thrown", "linear momentum drift per second", 100.0 * drift, 0.1, true, "%"});
}

// A strip 2.5 cm wide of `material`, `free` of it beyond a 2 cm clamp (pinned), in cells
// of `cell`, lying flat 10 cm up; no breaks or hinges.
constexpr double kStripWidth = 0.025, kStripClamp = 0.02, kStripCell = 0.0025;
World clampedStrip(const FidelityOptions& o, const Material& material, double free, double cell,
                   const char* scene) {
    SheetSpec spec;
    spec.width = kStripWidth;
    spec.length = kStripClamp + free;
    spec.columns = static_cast<int>(std::lround(kStripWidth / cell)) + 1;
    spec.rows = static_cast<int>(std::lround(spec.length / cell)) + 1;
    spec.height = 0.1;
    spec.density = material.arealDensity;
    World w;
    w.scene = scene;
    w.sheet = buildRectangleSheet(spec);
    w.groundEnabled = false;
    applySolver(w.params, o);
    w.params.breaking = false;
    w.params.hinges = false;
    w.params.material = material;
    PinGroup clamp;
    for (Index i = 0; i < w.sheet.verts.size(); ++i)
        if (w.sheet.verts.X[i].y() + 0.5 * spec.length <= kStripClamp + 1e-9) {
            clamp.vertices.push_back(i);
            w.sheet.verts.pinned[i] = 1;
        }
    w.script.pins.push_back(clamp);
    return w;
}

// Runs a clamped strip while its weight comes on and settles; returns the chord from the
// clamp's edge (the last pinned row) to the tip (the last row) at the end.
// The load comes on without a swing, as in the standard cantilever test, where the strip
// is slid over the edge at 2 mm/s (ASTM D1388; some 50 s for 10 cm) and its curvature
// only grows. Here gravity rises smoothly to g over `ramp` on the whole strip, then
// holds: tissue's 10 cm strip went at most 0.4° past where it came to rest. Let go flat,
// the strip swung down with no air to slow it, and tissue passed its yield curvature at
// the clamp in that first swing and set at 73.6° where Peirce says 60.5°
// (docs/material.md, "Cantilever").
Vec3 chordUnderWeight(const World& w, bool quick) {
    const double ramp = quick ? 1.5 : 2.0;
    const double g = w.params.gravity;
    Simulation sim(w);
    const int steps = stepsFor(w, ramp + (quick ? 1.0 : 2.0));
    for (int k = 0; k < steps; ++k) {
        const double u = std::min(1.0, (k + 1) * w.params.dt / ramp);
        sim.world().params.gravity = g * u * u * (3.0 - 2.0 * u);
        if (sim.step() != StepStatus::Ok) break;
    }
    const Sheet& s = sim.world().sheet;
    double edgeRow = -std::numeric_limits<double>::infinity(), tipRow = edgeRow;
    for (Index i = 0; i < s.verts.size(); ++i) {
        tipRow = std::max(tipRow, s.verts.X[i].y());
        if (s.verts.pinned[i]) edgeRow = std::max(edgeRow, s.verts.X[i].y());
    }
    Vec3 tip = Vec3::Zero(), edge = Vec3::Zero();
    int nt = 0, ne = 0;
    for (Index i = 0; i < s.verts.size(); ++i) {
        if (s.verts.X[i].y() >= tipRow - 1e-9) {
            tip += s.verts.x[i];
            ++nt;
        }
        if (std::abs(s.verts.X[i].y() - edgeRow) < 1e-9) {
            edge += s.verts.x[i];
            ++ne;
        }
    }
    return tip / nt - edge / ne;
}

// The strip on a table, `overhang` of it sticking out: the tip-chord angle at rest
// (radians).
double cantileverAngle(const FidelityOptions& o, const Material& material, double overhang,
                       bool quick) {
    const Vec3 chord =
        chordUnderWeight(clampedStrip(o, material, overhang, kStripCell, "cantilever"), quick);
    return std::atan2(-chord.y(), chord.z());
}

void cantileverChecks(const FidelityOptions& o, std::vector<FidelityRow>& rows) {
    const Material& m = o.material;
    const double w = m.arealDensity * 9.81;
    const double c = std::cbrt(m.bendingStiffness / w);
    for (double overhang : {0.05, 0.10}) {
        const double sim = cantileverAngle(o, m, overhang, o.quick);
        const double peirce = peirceAngle(overhang, c);
        rows.push_back(
            {"cantilever " + std::to_string(int(std::lround(overhang * 100))) + " cm",
             "tip-chord angle " + degrees(sim) + "° vs Peirce " + degrees(peirce) + "°, deviation",
             100.0 * std::abs(sim / peirce - 1.0), 10.0, true, "%"});
    }
    Material card;
    materialPreset("card", card);
    const double office = cantileverAngle(o, m, 0.10, o.quick);
    const double stiffer = cantileverAngle(o, card, 0.10, o.quick);
    rows.push_back({"cantilever card vs " + m.name, "10 cm droop of card / of this material",
                    stiffer / office, 1.0, true, "×"});
}

// Greenhill's column: a strip standing upright, clamped at its foot, buckles under its
// own weight once it is taller than 1.986 (D / ρg)^(1/3) (Greenhill 1881; Timoshenko &
// Gere, "Theory of Elastic Stability", §2.9). Below that, a strip that leans a little
// leans further under its weight, the more the nearer it is to the critical height.
// The strip here is 2.5 cm wide and stands `height` above a 2 cm clamp, leaning
// kGreenhillLean from the vertical (every real column has some imperfection); its weight
// comes on smoothly as in the cantilever. Returns the tip-chord angle from the vertical
// through the clamp's edge at rest (radians). Cells of 2.5 mm, the cantilever's: with
// the bending damping whole on every cell such a column folded at its foot under a
// fraction of its buckling load, and the check used 6.25 mm (docs/material.md,
// "Bending damping per cell").
constexpr double kGreenhillLean = kPi / 180.0;
double greenhillTipAngle(const FidelityOptions& o, double height) {
    World w = clampedStrip(o, o.material, height, kStripCell, "greenhill");
    Sheet& s = w.sheet;
    const double length = kStripClamp + height;
    for (Index i = 0; i < s.verts.size(); ++i) {
        const double up = s.verts.X[i].y() + 0.5 * length; // from the foot
        s.verts.x[i] = Vec3(s.verts.X[i].x(), 0.1 + up * std::cos(kGreenhillLean),
                            up * std::sin(kGreenhillLean));
    }
    const Vec3 chord = chordUnderWeight(w, o.quick);
    return std::atan2(std::abs(chord.z()), chord.y());
}

void greenhillChecks(const FidelityOptions& o, std::vector<FidelityRow>& rows) {
    const Material& m = o.material;
    const double c = std::cbrt(m.bendingStiffness / (m.arealDensity * 9.81));
    const double critical = greenhillCriticalHeight(c);
    const std::string cm = cLocaleNumber(100.0 * critical, std::chars_format::fixed, 1);
    // Where the column stands, the height whose linear theory leans as far as the
    // simulated one: the critical height the simulation behaves as if it had.
    const double below = 0.8 * critical;
    const double leaned = greenhillTipAngle(o, below);
    // (Between a tenth of it and the critical height: a column that folded reads 20 %
    // low, one that swung back past its clamp 900 % high.)
    double lo = 0.1 * below, hi = critical;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (greenhillTipChordAngle(mid, c, kGreenhillLean) < leaned ? lo : hi) = mid;
    }
    const double behavesAs = critical * below / (0.5 * (lo + hi));
    rows.push_back({"Greenhill column " + cm + " cm",
                    "critical height from the lean at 0.8 of it (" + degrees(leaned) +
                        "° vs theory " + degrees(greenhillTipChordAngle(below, c, kGreenhillLean)) +
                        "°), deviation",
                    100.0 * std::abs(behavesAs / critical - 1.0), 10.0, true, "%"});
    rows.push_back({"Greenhill column 1.2 × " + cm + " cm", "tip-chord angle from the vertical",
                    greenhillTipAngle(o, 1.2 * critical) * 180.0 / kPi, 45.0, false, "°"});
}

// The desk inclined by `alpha`: returns the distance the sheet's centre of mass slid
// along the slope in the last `window` seconds and its acceleration over them.
struct Slide {
    double distance = 0.0, acceleration = 0.0;
};
Slide inclineRun(const FidelityOptions& o, double alpha, double seconds) {
    SheetSpec spec = a4Spec(8);
    spec.width = 0.1;
    spec.length = 0.1;
    spec.rows = 8;
    spec.density = o.material.arealDensity;
    World w;
    w.scene = "incline";
    w.sheet = buildRectangleSheet(spec);
    applySolver(w.params, o);
    w.params.material = o.material;
    w.params.breaking = false;
    w.params.gravityTilt = alpha;
    Simulation sim(w);
    const double mass = totalMass(sim.world().sheet);
    const auto comX = [&] {
        double x = 0.0;
        const Sheet& s = sim.world().sheet;
        for (Index i = 0; i < s.verts.size(); ++i) x += s.verts.m[i] * s.verts.x[i].x();
        return x / mass;
    };
    const double x0 = comX();
    const int steps = stepsFor(w, seconds);
    for (int k = 0; k < steps && sim.step() == StepStatus::Ok; ++k) {
    }
    Slide r;
    r.distance = comX() - x0;
    r.acceleration = momentum(sim.world().sheet).x() / (mass * sim.world().time);
    return r;
}

void inclineChecks(const FidelityOptions& o, std::vector<FidelityRow>& rows) {
    const Material& m = o.material;
    const double stick = std::atan(m.groundStaticFriction) - 5.0 * kPi / 180.0;
    const double slide = std::atan(m.groundStaticFriction) + 10.0 * kPi / 180.0;
    const double seconds = o.quick ? 0.5 : 1.0;
    const Slide still = inclineRun(o, stick, seconds);
    rows.push_back(
        {"incline " + std::to_string(int(std::lround(stick * 180 / kPi))) + "° (below atan μs)",
         "distance slid", 1000.0 * std::abs(still.distance), 0.1, true, "mm"});
    const Slide moving = inclineRun(o, slide, seconds);
    const double coulomb = 9.81 * (std::sin(slide) - m.groundKineticFriction * std::cos(slide));
    rows.push_back({"incline " + std::to_string(int(std::lround(slide * 180 / kPi))) + "° (above)",
                    "acceleration vs g(sin α - μk cos α), deviation",
                    100.0 * std::abs(moving.acceleration / coulomb - 1.0), 5.0, true, "%"});
}

// An artist's pushing, as the editor does it: the tool follows a target pressed 0.6 of
// its radius into the sheet (the desk stops it), at the editor's speed limit of
// 1.5 m/s, in 2 s strokes across the sheet in turning directions with 1 s lifted
// between them. Stretch is measured during and after, and the mesh must stay bounded.
void strokeChecks(const FidelityOptions& o, std::vector<FidelityRow>& rows) {
    World start = configured(*makeScene("press"), o);
    start.script.sphereKeys.clear();
    const double radius = 0.03;
    start.sphere.radius = radius;
    start.sphere.center = Vec3(0.0, 0.1, 0.0);
    start.sphere.active = true;
    Simulation sim(start);
    const Index startVertices = sim.world().sheet.verts.size();
    const double seconds = o.quick ? 6.0 : 15.0;
    const int steps = stepsFor(sim.world(), seconds);
    StretchRun stretch;
    for (int k = 0; k < steps; ++k) {
        World& w = sim.world();
        const double t = w.time;
        const int stroke = static_cast<int>(t / 3.0);
        const double u = std::fmod(t, 3.0), heading = 1.3 * stroke;
        Vec3 target(0.0, 0.1, 0.0);
        if (u < 2.0) {
            const double along = (u / 2.0 - 0.5) * 0.16;
            target = Vec3(std::cos(heading) * along, 0.4 * radius, std::sin(heading) * along);
        }
        Vec3 move = target - w.sphere.center;
        const double limit = 1.5 * w.params.dt;
        if (move.norm() > limit) move *= limit / move.norm();
        w.sphere.center += move;
        w.sphere.velocity = move / w.params.dt;
        if (sim.step() != StepStatus::Ok) {
            stretch.blewUp();
            break;
        }
        stretch.add(computeStats(sim.world().sheet));
    }
    addStretchRows(rows, "push strokes", stretch);
    rows.push_back({"push strokes", "vertices after the strokes / at the start",
                    double(sim.world().sheet.verts.size()) / double(startVertices), 3.0, true,
                    "×"});
}

} // namespace

double peirceAngle(double length, double bendingLength) {
    const double target = std::pow(length / bendingLength, 3.0);
    double lo = 0.0, hi = 0.5 * kPi - 1e-9;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (8.0 * std::tan(mid) / std::cos(0.5 * mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double greenhillCriticalHeight(double bendingLength) {
    return 1.986 * bendingLength;
}

double greenhillTipChordAngle(double height, double bendingLength, double lean) {
    // The slope θ(s) of the column against the vertical, s from the clamp: D θ'' =
    // −ρg (H − s) θ (the weight above s turns it further), θ(0) = lean, θ'(H) = 0 (no
    // moment at the tip). Linear in the unknown θ'(0): shoot twice (RK4), combine.
    const double k = 1.0 / (bendingLength * bendingLength * bendingLength); // ρg / D
    constexpr int kSteps = 2000;
    const double h = height / kSteps;
    struct State {
        double slope, change, lateral; // θ, θ', and ∫θ
    };
    const auto shoot = [&](double change0) {
        const auto f = [&](double s, const State& y) {
            return State{y.change, -k * (height - s) * y.slope, y.slope};
        };
        const auto add = [](const State& y, const State& d, double t) {
            return State{y.slope + t * d.slope, y.change + t * d.change, y.lateral + t * d.lateral};
        };
        State y{lean, change0, 0.0};
        for (int i = 0; i < kSteps; ++i) {
            const double s = i * h;
            const State k1 = f(s, y), k2 = f(s + 0.5 * h, add(y, k1, 0.5 * h));
            const State k3 = f(s + 0.5 * h, add(y, k2, 0.5 * h)), k4 = f(s + h, add(y, k3, h));
            y = State{y.slope + h / 6 * (k1.slope + 2 * k2.slope + 2 * k3.slope + k4.slope),
                      y.change + h / 6 * (k1.change + 2 * k2.change + 2 * k3.change + k4.change),
                      y.lateral +
                          h / 6 * (k1.lateral + 2 * k2.lateral + 2 * k3.lateral + k4.lateral)};
        }
        return y;
    };
    const State a = shoot(0.0), b = shoot(1.0);
    const State tip = shoot(-a.change / (b.change - a.change));
    return std::atan2(tip.lateral, height);
}

std::vector<FidelityRow> runFidelity(const FidelityOptions& o) {
    std::vector<FidelityRow> rows;
    pressChecks(o, rows);
    strokeChecks(o, rows);
    for (const char* scene : {"drape", "compress", "drop"})
        stretchCheck(o, scene, o.quick ? 1.5 : 5.0, rows);
    // Its gathered creases carry the lightest vertices of any scene, where the
    // sub-steps leave the most for the projection: before the projection's changes of
    // 2026-11-29 its first cycle broke the stretch bound while every scene above kept
    // it, and one seed's later cycles broke it again. So the full card runs all ten
    // cycles; --quick the first.
    stretchCheck(o, "crumple-cycles", (o.quick ? 1 : kCrumpleCycles) * kCrumpleCycleSeconds, rows);
    for (const char* orientation : {"flat", "tilted 45°", "hanging", "crumpled"})
        freeFallCheck(o, orientation, rows);
    momentumCheck(o, rows);
    cantileverChecks(o, rows);
    greenhillChecks(o, rows);
    inclineChecks(o, rows);
    return rows;
}

} // namespace pf
