#include "TestSheets.h"

#include "Rng.h"
#include "SheetBuilder.h"

namespace pf::test {

Sheet makeFoldedQuad() {
    Sheet s;
    s.density = 0.08;
    const Vec2 X[4] = {{-0.5, 0.0}, {0.5, 0.0}, {0.0, 0.5}, {0.0, -0.5}};
    const Vec3 x[4] = {{-0.4, 0.0, 0.0}, {0.4, 0.0, 0.0}, {0.0, 0.3, 0.4}, {0.0, 0.3, -0.4}};
    // Lumped mass: each triangle has rest area 0.25.
    const double share = s.density * 0.25 / 3.0;
    const double m[4] = {2 * share, 2 * share, share, share};
    for (int k = 0; k < 4; ++k) s.addVertex(x[k], Vec3::Zero(), m[k], X[k]);
    auto structural = [&](Index a, Index b) {
        return s.addSpring(a, b, s.materialDistance(a, b), SpringKind::Structural, true);
    };
    const Index eij = structural(0, 1), eir = structural(0, 2), erj = structural(2, 1);
    const Index ejl = structural(1, 3), eli = structural(3, 0);
    s.tris.push_back(Triangle{{0, 2, 1}, {eir, erj, eij}});
    s.tris.push_back(Triangle{{0, 1, 3}, {eij, ejl, eli}});
    s.springs.faces[eij] = {0, 1};
    s.springs.faces[eir] = {0, kNone};
    s.springs.faces[erj] = {0, kNone};
    s.springs.faces[ejl] = {1, kNone};
    s.springs.faces[eli] = {1, kNone};
    s.addSpring(2, 3, s.materialDistance(2, 3), SpringKind::Bending, false);
    return s;
}

Sheet makeJitteredSheet(int columns, int rows, unsigned seed) {
    SheetSpec spec;
    spec.columns = columns;
    spec.rows = rows;
    Sheet s = buildRectangleSheet(spec);
    Rng rng(seed);
    const double cell = spec.width / (columns - 1);
    for (Vec3& p : s.verts.x)
        p += 0.2 * cell *
             Vec3(rng.uniform() - 0.5, 2.0 * (rng.uniform() - 0.5), rng.uniform() - 0.5);
    return s;
}

void holdFarEdge(World& w, int resolution) {
    const SheetSpec spec = a4Spec(resolution);
    PinGroup held;
    for (int c = 0; c < spec.columns; ++c)
        held.vertices.push_back((spec.rows - 1) * spec.columns + c);
    for (Index i : held.vertices) w.sheet.verts.pinned[i] = 1;
    w.script.pins.push_back(held);
}

int stepUntilAsleep(Simulation& sim, int maxSteps) {
    for (int k = 0; k < maxSteps; ++k) {
        if (sim.asleep()) return k;
        if (sim.step() != StepStatus::Ok) return kStepFailed;
    }
    return sim.asleep() ? maxSteps : -1;
}

} // namespace pf::test
