// Where each method works and where it fails (../shared/notes/solver-facts.md), and
// the fix for the gravity the paper's step loses.
#include "Scenes.h"
#include "SheetStats.h"
#include "Simulation.h"
#include "SpringForce.h"
#include "SymplecticEulerIntegrator.h"

#include <Eigen/Eigenvalues>
#include <QtTest>

using namespace pf;

namespace {

enum class Outcome { Stable, Diverged, Overstrained };

// Runs a scene at resolution 7 with breaking off; a run fails on divergence (NaN or
// a blow-up) or on strain beyond 50 % at the end.
Outcome run(const char* scene, const char* integrator, int sweeps, bool clamp, double dt,
            double stiffnessScale, int steps) {
    SceneOptions o;
    o.resolution = 7;
    World w = *makeScene(scene, o);
    w.params.integrator = integrator;
    w.params.iterations = sweeps;
    w.params.clampCompressed = clamp;
    w.params.dt = dt;
    w.params.breaking = false;
    for (double& k : w.params.stiffness) k *= stiffnessScale;
    Simulation sim(std::move(w));
    for (int s = 0; s < steps; ++s)
        if (sim.step() != StepStatus::Ok) {
            qInfo("%s %s/%d clamp=%d h=%g k*%g: diverged at step %d", scene, integrator, sweeps,
                  clamp, dt, stiffnessScale, s);
            return Outcome::Diverged;
        }
    const double strain = computeStats(sim.world().sheet).maxStrain;
    if (strain > 0.5)
        qInfo("%s %s/%d clamp=%d h=%g k*%g: strain %.2f", scene, integrator, sweeps, clamp, dt,
              stiffnessScale, strain);
    return strain > 0.5 ? Outcome::Overstrained : Outcome::Stable;
}

constexpr double kSteps[] = {1.0 / 30, 1.0 / 480, 1.0 / 7680};
constexpr double kStiffness[] = {1.0, 100.0, 10000.0};

// One second of simulated time (at most 2000 steps); strain is judged at its end,
// after the transients of the start.
int stepsFor(double dt) {
    return std::min(2000, static_cast<int>(std::lround(1.0 / dt)));
}

// A sheet hanging straight down (springs along gravity) released at rest: centre-of-
// mass acceleration over 0.1 s divided by g. Exact backward Euler gives 1.
double fallRatio(const char* integrator, int sweeps, bool outside, double dt) {
    World w = *makeScene("drape");
    w.script.pins.clear();
    for (auto& p : w.sheet.verts.pinned) p = 0;
    for (Vec3& x : w.sheet.verts.x) x = Vec3(x.x(), 0.5 - (x.z() + 0.1485), 0.0);
    w.groundEnabled = false;
    w.params.integrator = integrator;
    w.params.iterations = sweeps;
    w.params.dt = dt;
    w.params.gravityOutsideFilter = outside;
    Simulation sim(std::move(w));
    const int n = static_cast<int>(std::lround(0.1 / dt));
    for (int k = 0; k < n; ++k) sim.step();
    double m = 0, p = 0;
    const auto& V = sim.world().sheet.verts;
    for (Index i = 0; i < V.size(); ++i) {
        m += V.m[i];
        p += V.m[i] * V.v[i].y();
    }
    return -(p / m) / (9.81 * n * dt);
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
                    QVERIFY2(run(scene, "jacobi", 1, true, dt, k, stepsFor(dt)) == Outcome::Stable,
                             qPrintable(QStringLiteral("%1 h=%2 k×%3")
                                            .arg(QLatin1String(scene))
                                            .arg(dt)
                                            .arg(k)));
    }

    void withoutTheClampTheCompressedSheetFailsAtLargeSteps() {
        // Compressed springs have a negative transverse stiffness; at large h²k/m it makes
        // W indefinite. Small steps still work.
        QVERIFY(run("compress", "jacobi", 1, false, 1.0 / 30, 1.0, stepsFor(1.0 / 30)) !=
                Outcome::Stable);
        QVERIFY(run("compress", "jacobi", 1, false, 1.0 / 7680, 1.0, stepsFor(1.0 / 7680)) ==
                Outcome::Stable);
    }

    void zeroSweepsFailsAtLargeStepsAndTwoSweepsOvershoot() {
        QVERIFY(run("compress", "jacobi", 0, true, 1.0 / 30, 10000.0, stepsFor(1.0 / 30)) !=
                Outcome::Stable);
        QVERIFY(run("compress", "jacobi", 0, true, 1.0 / 7680, 1.0, stepsFor(1.0 / 7680)) ==
                Outcome::Stable);
        // An even number of Jacobi applications can overshoot high-frequency modes.
        QVERIFY(run("drape", "jacobi", 2, true, 1.0 / 30, 10000.0, stepsFor(1.0 / 30)) !=
                Outcome::Stable);
    }

    void exactBackwardEulerNeverFails() {
        for (const char* scene : {"compress", "drape"})
            for (double k : kStiffness)
                for (double dt : kSteps)
                    QVERIFY2(run(scene, "backward-euler", 0, true, dt, k,
                                 std::min(120, stepsFor(dt))) == Outcome::Stable,
                             qPrintable(QStringLiteral("%1 h=%2 k×%3")
                                            .arg(QLatin1String(scene))
                                            .arg(dt)
                                            .arg(k)));
    }
};

QTEST_APPLESS_MAIN(TestSolverLab)
#include "test_solver_lab.moc"
