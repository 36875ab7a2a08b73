#pragma once

#include "Sheet.h"
#include "Types.h"

#include <vector>

namespace pf {

// The air's resistance to a sheet turning and fluttering through it.
//
// Real paper hanging from two corners stops swinging within a few swings: its
// broadside pushes air aside, and the drag (½ ρ C_d A v², about its own weight at
// 1 m/s for an A4 sheet) is as large as the pull that swings it. Without air the
// model's `drape` swung for more than a minute. Issue 9 also asks that a falling sheet
// fall at 1.00 g in any orientation, which real air would not allow; so the drag never
// acts on the centre of mass of a free sheet. It acts in two parts, each along each
// vertex's normal with the quadratic drag of its own area of paper:
// - the sheet's rigid rotation: each vertex's share of it, ω × (x − o), meets the drag,
//   and the torque of those drags slows that rotation, as a rigid change of the
//   velocities. A free sheet turns about its centre of mass (o), a pinned one about its
//   pin, or about the line through pins in a row (a rigid turn about them stretches
//   nothing); pins that span a plane, or pins that move (a hand, the Fold tool, a
//   scene's script), leave the turning to the paper;
// - what is left of each vertex's velocity after the rigid motion: the sheet flapping,
//   fluttering or twisting between its pins, vertex by vertex. What that drag would do
//   to the rigid motion is taken back out (its net impulse on a free sheet, so the
//   centre of mass moves exactly as without air, and its turn), so it slows only what
//   is left and can never add energy. Tissue's lower part twisting against its pinned
//   edge carried 77-88 % of its `drape`'s energy, which the rigid turn did not see: it
//   slept at 18.3 s, office at 5.9; with this part 5.6 and 5.0.
// The sheet's sliding in its own plane meets the air only while it swings as a
// pendulum in that plane (airSkinFriction below); otherwise it is left alone.
//
// A sheet swinging to and fro from its pins meets the air it stirred on the last
// stroke, and far more drag than in steady flow (oscillatingPlateDrag): with steady
// drag alone the swing died down to a few millimetres that lingered for 40 s.
//
// Constants: air at 20 °C and sea level, 1.20 kg/m³; a flat plate broadside to the
// flow, C_d = 1.17 (Hoerner, "Fluid-Dynamic Drag", 1965, ch. 3: square plate).
inline constexpr double kAirDensity = 1.20;           // kg/m³
inline constexpr double kPlateDragCoefficient = 1.17; // flat plate, broadside
// Air at 20 °C: 1.81·10⁻⁵ Pa·s / 1.20 kg/m³.
inline constexpr double kAirKinematicViscosity = 1.51e-5; // m²/s

// Applies the drag of one step of `dt` seconds to the velocities of the free vertices
// (pins move as their script says). Paper driven by pins that move is left to them: the
// caller does not call it then. The paper's areal density gives each vertex's mass per
// area, so the drag per mass is ρ C_d u² / (2 ρ_A); each vertex's drag over the step is
// the exact solution of that, u / (1 + dt k |u|), so the change takes energy at any
// step and never adds any. `gravity` is what a pinned sheet swings under; `normals` is
// scratch space. While the tool is pressed (`toolPressed`), the user is shaping the
// paper and its dent is not a flutter: the second part is left out, and the tool's
// strokes (and the scorecard's rows for them) are as they were measured. Paper held by
// pins that span a plane (pinned at three or four corners) meets neither part: its
// shape between them is the pins' (`crumple-cycles` gathers a sheet so).
void dragThroughAir(Sheet& sheet, double arealDensity, const Vec3& gravity, double dt,
                    std::vector<Vec3>& normals, bool toolPressed);

// The drag coefficient of a flat plate of `breadth` moving to and fro broadside through
// still air, `displacementAmplitude` either way. At a small swing the plate meets the
// vortices it shed on the last stroke, and the drag is far above steady flow's: Graham
// (J. Fluid Mech. 97, 1980, from the shedding at sharp edges, matching Keulegan &
// Carpenter's 1958 plate measurements) gives C_d ≈ 8 KC^(−1/3) at small
// Keulegan-Carpenter numbers KC = U T / D = 2π X / D. It falls to the steady plate's
// 1.17 at KC ≈ 320 and is held there beyond.
double oscillatingPlateDrag(double displacementAmplitude, double breadth);

// A sheet swinging as a pendulum in its own plane (hung from one pin, edge-on) pushes no
// air aside; the air's viscosity alone slows it. A plate moving to and fro in its own
// plane at angular frequency Ω drags a Stokes layer of thickness δ = √(2ν/Ω) with it
// (Stokes' second problem; Landau & Lifshitz, "Fluid Mechanics", §24), and the part of
// the wall's shear in phase with the plate's velocity u, the part that takes energy, is
// μ u / δ = ρ √(νΩ/2) u on each face. Both faces, per unit of the paper's mass: a
// linear drag of rate ρ √(2νΩ) / ρ_A (1/s), so a swing's amplitude dies as e^(−t/τ) with
// τ = 2 ρ_A / (ρ √(2νΩ)): 10 s for office paper swinging once a second. The layer holds
// while the swing is short of the sheet's length along it; a swing wider than that
// meets the steady (Blasius) layer, which drags more. Without it a sheet hung from one
// corner swung edge-on for minutes (its far corner at 0.44 m/s after a minute, 9 % of
// its energy gone in 20 s).
double airSkinFriction(double swingFrequency, double arealDensity);

} // namespace pf
