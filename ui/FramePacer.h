#pragma once

namespace pf {

// How many steps of dt the editor runs at a tick of its frame timer, so that the
// simulated time keeps up with the wall clock. A fixed four steps a tick lost time at
// every tick (a 1/60 s timer fires every 17 ms) and at every late one (the view and Xvfb
// share the machine's two cores): the editor ran at 0.98 of real time with the sheet at
// rest and the step costing 17 µs. Now a tick runs the steps due since the last one, and
// what it leaves over (less than a step) is owed to the next. A late tick is caught up
// to kCatchUpSeconds of steps at once, the rest dropped. A machine whose steps take
// longer than their dt cannot keep real time at all: catching up would only run more
// steps a tick and show fewer frames at the same pace, so it runs a frame's steps a
// tick, as before.
class FramePacer {
  public:
    static constexpr double kFrameSeconds = 1.0 / 60.0;
    static constexpr double kCatchUpSeconds = 2.0 * kFrameSeconds;

    // The steps to run at a tick `elapsed` seconds after the last one, when a step has
    // lately taken `stepCost` seconds of wall time (0: not known).
    int stepsFor(double elapsed, double dt, double stepCost = 0.0);
    // Forgets what is owed: after a pause the sheet goes on from now, not from then.
    // The pace is not known again until a second has passed.
    void restart();
    // Simulated seconds per wall-clock second over the last whole second of ticks, 1
    // until one has passed. Below 1 the paper moves slower than it would in the hand,
    // and a user cannot tell that from the picture alone: 1000 steps a second of a
    // crumpled sheet drew at 5 fps and ran at about a tenth of real time, unsaid.
    double pace() const { return pace_; }
    // Tells the pacer the wall time `seconds` that the `steps` of the last tick took.
    void stepped(int steps, double seconds);
    // Wall time per step over the pace's last whole second (the work told to stepped()
    // by then), 0 until one has passed. The last tick alone did not agree with the pace:
    // a user read "step 51822 µs · 0.54× real time" in the second after breaks made the
    // sheet slower (at most 0.08× at that cost), and "step 20 µs · 0.13×" once it slept.
    double stepSeconds() const { return stepSeconds_; }

  private:
    int stepsDue(double elapsed, double dt, double stepCost);

    double owed_ = 0.0; // seconds
    double windowWall_ = 0.0, windowSimulated_ = 0.0;
    double pace_ = 1.0;
    double windowStepWall_ = 0.0; // seconds the steps took, in the window
    int windowSteps_ = 0;
    double stepSeconds_ = 0.0;
};

} // namespace pf
