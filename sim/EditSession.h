#pragma once

#include "Simulation.h"

#include <optional>
#include <vector>

namespace pf {

// What a user does to a sheet, applied between steps: the tool follows a target at a
// bounded speed, a press of it is a stroke, and a stroke's damage (breaks and hinges)
// is undone through §4.2 recovery and done again. Plain C++, so the editor's
// simulation thread and anything headless drive the same code.
class EditSession {
  public:
    explicit EditSession(World world);

    // The tool follows its target no faster than this: a jump of the cursor across the
    // sheet must not teleport the tool through the paper.
    static constexpr double kMaxToolSpeed = 1.5; // m/s

    Simulation& simulation() { return sim_; }
    const World& world() const { return sim_.world(); }

    // A new sheet: the tool keeps its size and visibility, the stroke history is cleared.
    void replaceWorld(const World& world);
    // A different paper weighs differently: the masses follow its areal density.
    void setParams(const SimParams& params);

    struct StrokeEnd {
        int stroke = 0; // its index, for undoStroke / redoStroke
        int events = 0; // breaks and hinges it made
    };
    // Moves the tool's target; a release ends the stroke, which is returned when it
    // made any damage (a stroke without damage has nothing to undo).
    std::optional<StrokeEnd> setTool(const Vec3& target, double radius, bool visible, bool pressed);
    // The number of damage events recovered (or done again); nothing for an unknown stroke.
    std::optional<int> undoStroke(int stroke);
    std::optional<int> redoStroke(int stroke);

    // Steps `steps` times, moving the tool toward its target first in each. Stops at the
    // first step that is not Ok and returns its status.
    StepStatus advance(int steps);
    // While paused the tool still goes where the user points, without a step. True if it
    // moved.
    bool placeToolAtTarget();

  private:
    // What a stroke did, enough to undo it and do it again.
    struct StrokeEvent {
        Index event = kNone;
        EventKind kind = EventKind::Break;
        Index edge = kNone;
        double hingeRest = 0.0;
    };
    std::optional<StrokeEnd> endStroke();

    Simulation sim_;
    Vec3 toolTarget_ = Vec3::Zero();
    bool pressed_ = false;
    Index strokeStart_ = 0;
    std::vector<std::vector<StrokeEvent>> strokes_;
};

} // namespace pf
