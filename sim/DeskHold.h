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

} // namespace pf
