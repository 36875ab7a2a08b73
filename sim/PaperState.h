#pragma once

#include "Types.h"

#include <array>
#include <vector>

namespace pf {

// PaperState::deskSlide where no slide was measured in the step before.
inline constexpr double kSlideUnknown = -1.0;

// What the "xpbd" integrator carries from one step to the next beyond positions and
// velocities. It lives with the sheet so that a saved sheet resumes exactly and keeps
// its folds, and so that undo gives back the state the user saw.
struct PaperState {
    // Plastic bending: the rest value of a bending stencil's Σ k x, by the stencil's
    // vertices (unused slots kNone), in stencil order.
    struct PlasticBend {
        std::array<Index, 5> vertices{};
        Vec3 rest = Vec3::Zero();
        friend bool operator==(const PlasticBend&, const PlasticBend&) = default;
    };
    // The tool's hold on a triangle it presses onto the desk.
    struct ToolGrip {
        Index triangle = kNone;
        Vec3 barycentric = Vec3::Zero(); // the held point
        Vec3 offset = Vec3::Zero();      // where on the tool it is held, from its centre
        friend bool operator==(const ToolGrip&, const ToolGrip&) = default;
    };
    std::vector<PlasticBend> plastic;
    std::vector<ToolGrip> grips;
    // Steps in a row in which no vertex moved farther than a slow drift allows.
    int quietSteps = 0;
    // Each vertex's position averaged over the last steps (`mean`, none or one per
    // vertex), and the steps in a row in which none of those went farther than
    // kStillReach from where it was when they began (`from`): a sheet caught in a cycle
    // goes nowhere, though each step moves it (XpbdIntegrator::advance).
    struct StillWatch {
        int steps = 0;
        std::vector<Vec3> from;
        std::vector<Vec3> mean;
        void clear() {
            steps = 0;
            from.clear();
            mean.clear();
        }
        friend bool operator==(const StillWatch&, const StillWatch&) = default;
    };
    // Averaged over about the last eight steps (kStillAveraging): cycles of a few steps.
    StillWatch still;
    // Over about the last half second (kSlowStillAveraging): cycles of about a second.
    StillWatch slowStill;
    // How fast the sheet slid across the desk, as a whole, in the step before (m/s), or
    // for a sheet hanging from one pin onto it, how fast it turned about the vertical
    // through the pin (rad/s); or kSlideUnknown (sim/DeskHold.h). Which one it is follows
    // from the pins, and a change of pins wakes the sheet, which forgets it.
    double deskSlide = kSlideUnknown;
    friend bool operator==(const PaperState&, const PaperState&) = default;

    // The mesh changed under the sheet (a break, a hinge, a recovery) or its paper did:
    // the tool lets go (its triangles are renumbered) and the sheet wakes. Done where
    // the change is made, so that a sheet saved right after it resumes exactly.
    void meshChanged() {
        grips.clear();
        wake();
    }
    // Whatever held the sheet may be gone: it is quiet again only from here on.
    void wake() {
        quietSteps = 0;
        still.clear();
        slowStill.clear();
        deskSlide = kSlideUnknown;
    }
};

} // namespace pf
