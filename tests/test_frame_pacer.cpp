// The editor's pacing (ui/FramePacer): the steps run at each tick of the frame timer keep
// the simulated time with the wall clock, whatever the ticks' spacing, and a machine
// that falls behind is not asked for an ever longer catch-up.
#include "FramePacer.h"

#include <QTest>
#include <cmath>

using namespace pf;

namespace {
constexpr double kDt = 1.0 / 240.0;
}

class TestFramePacer : public QObject {
    Q_OBJECT

  private slots:
    void ticksOfAFrameRunAFramesSteps() {
        FramePacer pacer;
        for (int tick = 0; tick < 600; ++tick) QCOMPARE(pacer.stepsFor(1.0 / 60.0, kDt), 4);
    }

    void aTimerOfWholeMillisecondsKeepsRealTime_data() {
        QTest::addColumn<double>("tick");
        // QTimer counts whole milliseconds: 1/60 s rounded is 17 ms, where four steps a
        // tick ran 0.98 of real time; the editor ticks every 16 ms, 3.84 steps' time.
        QTest::newRow("17 ms") << 0.017;
        QTest::newRow("16 ms") << 0.016;
    }
    void aTimerOfWholeMillisecondsKeepsRealTime() {
        QFETCH(double, tick);
        FramePacer pacer;
        long long steps = 0;
        for (int k = 0; k < 6000; ++k) steps += pacer.stepsFor(tick, kDt);
        const long long due = std::llround(6000 * tick / kDt);
        QVERIFY2(steps >= due - 1 && steps <= due, qPrintable(QString::number(steps)));
    }

    void lateAndEarlyTicksAreEvenedOut() {
        FramePacer pacer;
        QCOMPARE(pacer.stepsFor(0.002, kDt), 0);  // early: nothing due yet
        QCOMPARE(pacer.stepsFor(0.015, kDt), 4);  // 17 ms owed: 4 steps, 0.33 ms left
        QCOMPARE(pacer.stepsFor(0.030, kDt), 7);  // late: 30.33 ms owed, 7 steps
        QCOMPARE(pacer.stepsFor(0.0125, kDt), 3); // the 1.17 ms left and 12.5 ms
    }

    void jitterNeverLosesOrGainsTime() {
        // Ticks 5-28 ms apart, 100 s of them: the steps match the time within one step.
        FramePacer pacer;
        double wall = 0.0;
        long long steps = 0;
        unsigned state = 12345;
        for (int tick = 0; tick < 6000; ++tick) {
            state = state * 1103515245u + 12345u;
            const double gap = 0.005 + 0.023 * ((state >> 8) % 1000) / 999.0;
            wall += gap;
            steps += pacer.stepsFor(gap, kDt);
        }
        const double simulated = steps * kDt;
        QVERIFY2(std::abs(simulated - wall) <= kDt,
                 qPrintable(QStringLiteral("%1 s simulated in %2 s").arg(simulated).arg(wall)));
    }

    void aLongStallIsDroppedPastTwoFrames() {
        FramePacer pacer;
        const int most = static_cast<int>(std::round(FramePacer::kCatchUpSeconds / kDt));
        QCOMPARE(most, 8);
        QCOMPARE(pacer.stepsFor(0.5, kDt), most);     // a dialog held the thread half a second
        QCOMPARE(pacer.stepsFor(1.0 / 60.0, kDt), 4); // and the rest was dropped
        // Ticks 50 ms apart on a machine that steps fast enough: two frames' steps each.
        for (int tick = 0; tick < 100; ++tick) QCOMPARE(pacer.stepsFor(0.05, kDt, 1e-4), most);
    }

    void aMachineThatCannotKeepUpRunsAFramesSteps() {
        // Steps of 6 ms against a dt of 4.2 ms: catching up would only make every tick,
        // and the frames the view gets, twice as far apart, at the same pace.
        FramePacer pacer;
        for (int tick = 0; tick < 100; ++tick) QCOMPARE(pacer.stepsFor(0.024, kDt, 0.006), 4);
        // Once the steps are quick again, the pacing goes on from there, owing nothing.
        QCOMPARE(pacer.stepsFor(0.010, kDt, 1e-4), 2);
        QCOMPARE(pacer.stepsFor(0.0070, kDt, 1e-4), 2);
    }

    // The pace is what the ticks gave over the last whole second: real time where the
    // machine keeps up, and where it cannot (steps of 6 ms against 4.2 ms of dt, four a
    // tick that comes every 24 ms), 4.2 / 6 of it. A pause forgets it.
    void thePaceIsSimulatedSecondsPerSecond() {
        FramePacer pacer;
        QCOMPARE(pacer.pace(), 1.0);
        for (int tick = 0; tick < 200; ++tick) pacer.stepsFor(0.016, kDt, 1e-4);
        QVERIFY2(std::abs(pacer.pace() - 1.0) < 0.02, qPrintable(QString::number(pacer.pace())));
        for (int tick = 0; tick < 100; ++tick) pacer.stepsFor(0.024, kDt, 0.006);
        QVERIFY2(std::abs(pacer.pace() - kDt / 0.006) < 1e-9,
                 qPrintable(QString::number(pacer.pace())));
        pacer.restart();
        QCOMPARE(pacer.pace(), 1.0);
    }

    // The step time said beside the pace is the mean over the same second: 6 ms steps
    // then 0.1 ms ones read 6 ms until a whole second of the quick ones has passed, as the
    // pace says 0.69× until then (the last tick alone said 0.1 ms beside 0.69×).
    void theStepTimeIsTheMeanOverThePacesSecond() {
        FramePacer pacer;
        const auto tick = [&](double elapsed, double cost) {
            const int steps = pacer.stepsFor(elapsed, kDt, cost);
            pacer.stepped(steps, steps * cost);
        };
        QCOMPARE(pacer.stepSeconds(), 0.0); // no second yet
        for (int k = 0; k < 50; ++k) tick(0.024, 0.006);
        QVERIFY(std::abs(pacer.stepSeconds() - 0.006) < 1e-12);
        QVERIFY(std::abs(pacer.pace() - kDt / 0.006) < 1e-9);
        for (int k = 0; k < 20; ++k) tick(0.016, 1e-4);
        QVERIFY(std::abs(pacer.stepSeconds() - 0.006) < 1e-12); // that second still
        for (int k = 0; k < 160; ++k) tick(0.016, 1e-4);
        QVERIFY(std::abs(pacer.stepSeconds() - 1e-4) < 1e-12);
        QVERIFY(std::abs(pacer.pace() - 1.0) < 0.02);
        pacer.restart();
        QCOMPARE(pacer.stepSeconds(), 0.0);
    }

    void aRestartForgetsWhatIsOwed() {
        FramePacer pacer;
        QCOMPARE(pacer.stepsFor(0.0035, kDt), 0); // 3.5 ms owed
        pacer.restart();
        QCOMPARE(pacer.stepsFor(0.001, kDt), 0);  // 1 ms, not 4.5 ms
        QCOMPARE(pacer.stepsFor(0.0032, kDt), 1); // 4.2 ms
    }

    void aChangedStepKeepsTheTimeOwed() {
        FramePacer pacer;
        QCOMPARE(pacer.stepsFor(0.006, kDt), 1);         // 1.83 ms left
        QCOMPARE(pacer.stepsFor(0.006, 1.0 / 960.0), 7); // 7.83 ms at 1.04 ms a step
    }

    void nothingRunsWithoutTimeOrAStep() {
        FramePacer pacer;
        QCOMPARE(pacer.stepsFor(0.0, kDt), 0);
        QCOMPARE(pacer.stepsFor(-1.0, kDt), 0);
        QCOMPARE(pacer.stepsFor(std::nan(""), kDt), 0);
        QCOMPARE(pacer.stepsFor(0.1, 0.0), 0);
        QCOMPARE(pacer.stepsFor(0.1, std::nan("")), 0);
        QCOMPARE(pacer.stepsFor(1.0 / 60.0, kDt), 4); // and nothing was owed from those
    }
};

QTEST_APPLESS_MAIN(TestFramePacer)
#include "test_frame_pacer.moc"
