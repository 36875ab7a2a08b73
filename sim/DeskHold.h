#pragma once

#include "Sheet.h"
#include "Types.h"

#include <cstdint>
#include <vector>

namespace pf {

// Coulomb's law for the sheet as a whole on the desk.
//
// Inside a step, the sub-steps and the stretch projection can disagree on where a
// light crease vertex belongs (docs/material.md, "What is open"): each sub-step throws
// it out and the projection puts it back. Every such swing slips vertices on the desk
// past their static friction, one way and back, and the two halves of the swing do not
// cancel. So a folded sheet whose shape no longer changed slid across the desk as a
// rigid body, for ever, with nothing pushing it: 0.2-4 mm/s for office paper, up to
// 17 mm/s for card.
//
// Real paper cannot do that. Its internal forces sum to nothing, gravity presses it
// onto the desk, and the desk's friction slows whatever slides on it by μk·g (less any
// pull down a tilted desk). So, unless a tool, a pin or a hand holds the sheet, its
// rigid slide across the desk (how the vertices the desk holds up shift and turn,
// together, over the step) may only slow down from one step to the next, by at least
// that, and once stopped it stays stopped. What it gains beyond that
// is undone, and only that: the shape of the sheet is never touched. While the sheet
// as a whole rises or falls faster than friction's μk·g·dt (it lands, topples, or a
// flap falls onto the rest), its lifted part may push the part on the desk, and the
// slide is not measured.
struct DeskHoldScene {
    Vec3 gravity = Vec3::Zero(); // acceleration, with any tilt of the desk
    double dt = 0.0;
    double kineticFriction = 0.0;
};

// The caller has made sure that only the desk and gravity act on the sheet (no pins, no
// hand, no tool within reach), and says which vertices the desk held up in this step
// (contact). slide is the slide's speed at the step before (m/s, or kSlideUnknown) and
// becomes this step's. Returns whether a part of the step's rigid motion was undone.
bool holdOnDesk(Vertices& verts, const std::vector<Vec3>& stepStart,
                const std::vector<std::uint8_t>& contact, const DeskHoldScene& scene,
                double& slide);

// The same law for a sheet hanging from one still pin with a part of it on the desk.
// Nothing but the desk's friction (and the air) can turn such a sheet about the
// vertical through its pin: gravity, the pin's pull and the desk's push are vertical
// or act on that axis. Yet in the model the desk's friction turned it, for good: the
// bending solve, once every few sub-steps, kicks the corner on the desk back against
// the turn, the desk's friction in that sub-step stops the kick, and in the sub-steps
// between, where the corner meets no friction, the sheet carries it on (docs/material.md,
// "What is open": office paper turned at 0.12-0.14 rad/s after a user took out one of
// the `drape`'s two pins). Real paper turning so has its corner slide on the desk,
// whose friction, μk times the corner's load at its distance from the axis, slows the
// turn. So the sheet's rigid turn about that vertical (fitted to all its free vertices'
// moves over the step) may only slow down from one step to the next, by at least that
// torque over the sheet's moment of inertia about the axis, the load being what the
// desk pushed up on each vertex over the step (deskImpulse, N·s). What it gains beyond
// that is undone, as a rigid turn of the whole sheet about the axis, which moves the pin
// not at all and changes no length. turnRate is the turn's rate at the step before (rad/s,
// or kSlideUnknown) and becomes this step's. Returns whether a part was undone.
bool holdTurnOnDesk(Vertices& verts, const Vec3& pin, const std::vector<Vec3>& stepStart,
                    const std::vector<double>& deskImpulse, const DeskHoldScene& scene,
                    double& turnRate);

} // namespace pf
