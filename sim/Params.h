#pragma once

#include "Material.h"
#include "Sheet.h"

#include <array>
#include <string>

namespace pf {

// Everything that steers a step. Plain data: the editor edits it, files store it.
struct SimParams {
    // Paper §4.1 and §5 (defaults: the paper's Fig. 13).
    double phi = 0.1;  // fragility: scales the normal dot products of Eq. 10
    double psi = 0.25; // recursive-break tendency: scales the offset of Eq. 11
    // Crumple sharpness of the §4.3 subdivision: a look, saved with the sheet, that no
    // step reads. The editor keeps it with the renderer (RenderOptions::sigma).
    double sigma = 1.0;

    double dt = 1.0 / 240.0;
    int iterations = 1; // Jacobi sweeps after the initial estimate (Eq. 6)
    std::string integrator = "xpbd";
    // The paper the sheet is made of; used by "xpbd" (the other integrators keep the
    // per-kind stiffness below, the paper's springs).
    Material material;
    int substeps = 40; // "xpbd": sub-steps per step (docs/material.md: 32 left 1.08 % stretch)
    // "xpbd": Rayleigh damping of bending, β in seconds (damping force β Q v). It acts
    // on bending motion only, so it leaves free fall and momentum alone.
    double bendingDamping = 0.01;

    // Per spring kind, indexed by SpringKind. Stiffness in N/m, damping in N·s/m.
    std::array<double, kSpringKindCount> stiffness{100.0, 10.0, 100.0, 10.0};
    std::array<double, kSpringKindCount> damping{0.02, 0.002, 0.02, 0.002};

    // "xpbd": how hard the tool presses the paper onto the desk (N); its grip is at most
    // the tool's friction coefficient times this.
    double toolForce = 2.0;

    double gravity = 9.81; // m/s^2 along -y
    // "xpbd": gravity tilted by this angle (radians) toward +x, which is the same as a
    // desk inclined by it. Only the fidelity scorecard's incline uses it; not saved.
    double gravityTilt = 0.0;

    // Start the Jacobi iteration at Δv = h·g (gravity integrated outside the implicit
    // filter) instead of at 0 as Eq. 6 does. A rigid translation then falls exactly,
    // because A·(h g 1) = M·h g; the iteration matrix, and so stability, is unchanged.
    // Off reproduces the paper, which divides gravity by W (docs/solver-lab.md).
    bool gravityOutsideFilter = false;

    // Clamp (1 - L/l) at zero in the Jacobian of a compressed spring so that the
    // system matrix stays positive definite (docs/model.md, Integrators).
    bool clampCompressed = true;

    bool breaking = true;
    // "xpbd": the paper's layers touch instead of passing through each other.
    bool selfContact = true;
    bool hinges = true;
    // A hinge is inserted when |x_r - x_l| falls below this fraction of its rest distance.
    double hingeThreshold = 0.5;
    // Eq. 10 is a probability per this much growth of an edge's contraction beyond any
    // it carried before (docs/model.md, Breaking): breaks follow loading, not time.
    double breakReferenceContraction = 0.005;
    // The jacobi family's contact friction is a fraction per reference step of this length.
    double breakReferenceStep = 1.0 / 60.0;

    // Contact: fraction of tangential velocity removed per step while touching.
    double groundFriction = 0.6;
    double sphereFriction = 0.6;

    friend bool operator==(const SimParams&, const SimParams&) = default;

    double stiffnessOf(SpringKind k) const { return stiffness[static_cast<int>(k)]; }
    double dampingOf(SpringKind k) const { return damping[static_cast<int>(k)]; }
};

} // namespace pf
