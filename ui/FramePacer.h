#pragma once

namespace pf {

// How many steps of dt the editor runs at a tick of its frame timer, so that the
// simulated time keeps up with the wall clock. A fixed count per tick lost time whenever
// a tick came late (the view and Xvfb share the machine's two cores) and at every tick,
// since a 1/60 s timer fires every 17 ms: the editor ran at 0.86-0.95 of real time with
// the sheet asleep and the step costing 19 µs. What a tick leaves over (less than a
// step) is owed to the next one. Late ticks are caught up to kCatchUpSeconds of steps
// at once; beyond that the debt is dropped: a machine that cannot step in real time
// would only run more steps per tick, and show fewer frames, at the same pace.
class FramePacer {
  public:
    static constexpr double kCatchUpSeconds = 2.0 / 60.0;

    // The steps to run at a tick `elapsed` seconds after the last one.
    int stepsFor(double elapsed, double dt);
    // Forgets what is owed: after a pause the sheet goes on from now, not from then.
    void restart() { owed_ = 0.0; }

  private:
    double owed_ = 0.0; // seconds
};

} // namespace pf
