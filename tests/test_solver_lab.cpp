// Where each method works and where it fails (../shared/notes/solver-facts.md), and
// the fix for the gravity the paper's step loses.
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"
#include "SolverMetrics.h"
#include "SpringForce.h"
#include "StabilityProbe.h"
#include "SymplecticEulerIntegrator.h"

#include <Eigen/Eigenvalues>
#include <QTest>

using namespace pf;

namespace {

// One cell of the map (sim/StabilityProbe.h): resolution 7, 1 s of simulated time or
// at most 2000 steps, breaking off; strain is judged at the end, after the start's
// transients.
bool stable(const char* scene, const char* integrator, int sweeps, bool clamp, double dt,
            double stiffnessScale) {
    StabilityCase c;
    c.scene = scene;
    c.integrator = integrator;
    c.sweeps = sweeps;
    c.clampCompressed = clamp;
    c.dt = dt;
    c.stiffnessScale = stiffnessScale;
    if (c.integrator == "backward-euler") c.maxSteps = 120; // CG is slow; failures show early
    const StabilityResult r = probeStability(c);
    if (r.outcome != StabilityOutcome::Stable)
        qInfo("%s %s/%d clamp=%d h=%g k*%g (a=%.3g): %s after %d steps, strain %.2f", scene,
              integrator, sweeps, clamp, dt, stiffnessScale, r.a, outcomeName(r.outcome), r.steps,
              r.endStrain);
    return r.outcome == StabilityOutcome::Stable;
}

constexpr double kSteps[] = {1.0 / 30, 1.0 / 480, 1.0 / 7680};
constexpr double kStiffness[] = {1.0, 100.0, 10000.0};

double fallRatio(const char* integrator, int sweeps, bool outside, double dt) {
    SimParams p;
    p.integrator = integrator;
    p.iterations = sweeps;
    p.gravityOutsideFilter = outside;
    p.dt = dt;
    return freeFallRatio(p);
}

} // namespace

class TestSolverLab : public QObject {
    Q_OBJECT

  private slots:
    void gravityOutsideTheFilterFallsAtG() {
        const double paper = fallRatio("jacobi", 1, false, 1.0 / 240);
        const double fixed = fallRatio("jacobi", 1, true, 1.0 / 240);
        const double exact = fallRatio("backward-euler", 0, false, 1.0 / 240);
        qInfo("hanging sheet, h = 1/240: a/g paper %.4f, gravity outside the filter %.6f, backward "
              "Euler %.6f",
              paper, fixed, exact);
        QVERIFY(paper < 0.05);                 // the paper's step loses almost all of gravity
        QVERIFY(std::abs(fixed - 1.0) < 1e-6); // a rigid translation is exact
        QVERIFY(std::abs(exact - 1.0) < 1e-6);
        QVERIFY(std::abs(fallRatio("jacobi-scalar", 1, true, 1.0 / 60) - 1.0) < 1e-6);
    }

    void symplecticEulerFailsJustAboveItsLimit() {
        // The exact limit is h = 2/ω_max with ω_max² the largest eigenvalue of
        // M^-1/2 K M^-1/2 at rest (free sheet, no damping, no gravity).
        SceneOptions o;
        o.resolution = 6;
        World w = *makeScene("drape", o);
        w.script.pins.clear();
        for (auto& p : w.sheet.verts.pinned) p = 0;
        w.groundEnabled = false;
        w.params.gravity = 0.0;
        w.params.damping.fill(0.0);
        w.params.breaking = w.params.hinges = false;
        w.params.integrator = "symplectic";
        const Sheet& s = w.sheet;
        const Index n = s.verts.size();
        Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n);
        for (Index k = 0; k < s.springs.size(); ++k) {
            const Index a = s.springs.a[k], b = s.springs.b[k];
            const Mat3 B =
                evaluateSpring(s.verts.x[a], s.verts.x[b], Vec3::Zero(), Vec3::Zero(),
                               s.springs.rest[k], w.params.stiffnessOf(s.springs.kind[k]), 0, true)
                    .K;
            K.block<3, 3>(3 * a, 3 * a) += B;
            K.block<3, 3>(3 * b, 3 * b) += B;
            K.block<3, 3>(3 * a, 3 * b) -= B;
            K.block<3, 3>(3 * b, 3 * a) -= B;
        }
        Eigen::VectorXd invSqrtM(3 * n);
        for (Index i = 0; i < n; ++i)
            invSqrtM.segment<3>(3 * i).setConstant(1.0 / std::sqrt(s.verts.m[i]));
        const Eigen::MatrixXd A = invSqrtM.asDiagonal() * K * invSqrtM.asDiagonal();
        const double omegaMax =
            std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff());
        const double limit = 2.0 / omegaMax;
        QVERIFY(symplecticStepLimit(s, w.params) <= limit * (1 + 1e-9)); // Gershgorin is sufficient
        qInfo("symplectic Euler limit 2/omega_max = %.3g s (Gershgorin bound %.3g s)", limit,
              symplecticStepLimit(s, w.params));

        Rng rng(3); // a small random disturbance excites every mode
        for (Vec3& x : w.sheet.verts.x)
            x += 1e-5 * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
        auto survives = [&](double h) {
            World t = w;
            t.params.dt = h;
            Simulation sim(std::move(t));
            for (int k = 0; k < 3000; ++k)
                if (sim.step() != StepStatus::Ok) return false;
            return true;
        };
        QVERIFY(survives(0.95 * limit));
        QVERIFY(!survives(1.05 * limit));
    }

    void oneSweepWithTheClampSurvivesTheWholeGrid() {
        for (const char* scene : {"compress", "drape"})
            for (double k : kStiffness)
                for (double dt : kSteps)
                    QVERIFY2(stable(scene, "jacobi", 1, true, dt, k),
                             qPrintable(QStringLiteral("%1 h=%2 k×%3")
                                            .arg(QLatin1String(scene))
                                            .arg(dt)
                                            .arg(k)));
    }

    void withoutTheClampTheCompressedSheetFailsAtLargeSteps() {
        // Compressed springs have a negative transverse stiffness; at large h²k/m it makes
        // W indefinite. Small steps still work.
        QVERIFY(!stable("compress", "jacobi", 1, false, 1.0 / 30, 1.0));
        QVERIFY(stable("compress", "jacobi", 1, false, 1.0 / 7680, 1.0));
    }

    void zeroSweepsFailsAtLargeStepsAndTwoSweepsOvershoot() {
        QVERIFY(!stable("compress", "jacobi", 0, true, 1.0 / 30, 10000.0));
        QVERIFY(stable("compress", "jacobi", 0, true, 1.0 / 7680, 1.0));
        // An even number of Jacobi applications can overshoot high-frequency modes.
        QVERIFY(!stable("drape", "jacobi", 2, true, 1.0 / 30, 10000.0));
    }

    void xpbdSurvivesEveryStepAtPapersStiffness() {
        // The map's rows are the springs' stiffness; xpbd takes it as E·t (100 N/m × the
        // scale: ×100 is 10⁴ N/m, a fifth of tissue's; ×10⁴ is 10⁶ N/m, near card's).
        for (const char* scene : {"drape", "compress"})
            for (double k : {100.0, 10000.0})
                for (double dt : {1.0 / 480, 1.0 / 7680})
                    QVERIFY2(stable(scene, "xpbd", 0, true, dt, k),
                             qPrintable(QStringLiteral("%1 h=%2 k×%3")
                                            .arg(QLatin1String(scene))
                                            .arg(dt)
                                            .arg(k)));
        QVERIFY(stable("drape", "xpbd", 0, true, 1.0 / 30, 10000.0));
        // At 30 steps a second the edges `compress` drives together are crushed (86-96 %
        // shorter) before the sheet can arch out of their way, at every stiffness.
        QVERIFY(!stable("compress", "xpbd", 0, true, 1.0 / 30, 100.0));
        QVERIFY(!stable("compress", "xpbd", 0, true, 1.0 / 30, 10000.0));
        // Softer than any paper (E·t = 100 N/m with office paper's D) `compress` is crushed
        // at small steps too. Its fast projection pumped energy into it there (131 J at
        // 1/1920 s) while it stopped after four Newton iterations; iterating to the bound,
        // as it does where pins hold the paper, it is crushed instead (docs/solver-lab.md).
        StabilityCase soft;
        soft.scene = "compress";
        soft.integrator = "xpbd";
        soft.dt = 1.0 / 1920;
        soft.stiffnessScale = 1.0;
        const StabilityResult crushed = probeStability(soft);
        QCOMPARE(crushed.outcome, StabilityOutcome::Overstrained);
        QVERIFY2(crushed.peakKinetic < 1.0, qPrintable(QString::number(crushed.peakKinetic)));
    }

    void xpbdLeavesASheetSofterThanPaperToItsSubSteps() {
        // The fast projection pulls every stretched edge back to its rest length and gives
        // the vertices that move's velocity: right for paper, which barely stretches, but
        // a sheet of 100 N/m (the map's ×1) is stretched again by its own weight every
        // step, and the pulls pumped energy into it. Around the map's ×1 `drape` cell at
        // 1/7680 s (resolutions 6-9; steps of 1/7000, 1/7680 and 1/8500 s) it blew up in
        // 8 of these 12 cells, and at ×10 in 2 (in 8 and 3 once the air slowed the
        // sheet's turning). Softer than kPaperStiffness the sub-steps alone now give the
        // sheet the stretch its stiffness implies.
        int failed = 0;
        for (const double k : {1.0, 10.0})
            for (const int resolution : {6, 7, 8, 9})
                for (const double dt : {1.0 / 7000, 1.0 / 7680, 1.0 / 8500}) {
                    StabilityCase c;
                    c.scene = "drape";
                    c.integrator = "xpbd";
                    c.dt = dt;
                    c.stiffnessScale = k;
                    c.resolution = resolution;
                    const StabilityResult r = probeStability(c);
                    if (r.outcome != StabilityOutcome::Stable) {
                        ++failed;
                        qInfo("drape k×%g resolution %d h=1/%.0f: %s after %d steps (%.3g J)", k,
                              resolution, 1.0 / dt, outcomeName(r.outcome), r.steps, r.peakKinetic);
                    }
                }
        QCOMPARE(failed, 0);
    }

    void exactBackwardEulerNeverFails() {
        for (const char* scene : {"compress", "drape"})
            for (double k : kStiffness)
                for (double dt : kSteps)
                    QVERIFY2(stable(scene, "backward-euler", 0, true, dt, k),
                             qPrintable(QStringLiteral("%1 h=%2 k×%3")
                                            .arg(QLatin1String(scene))
                                            .arg(dt)
                                            .arg(k)));
    }
};

QTEST_APPLESS_MAIN(TestSolverLab)
#include "test_solver_lab.moc"
