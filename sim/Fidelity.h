#pragma once

#include "Material.h"

#include <string>
#include <vector>

namespace pf {

// One line of the fidelity scorecard: a measured value against a bound taken from
// physics the project did not write (Peirce's cantilever, Coulomb's incline, free fall)
// or from what paper does (it barely stretches, it comes to rest).
struct FidelityRow {
    std::string check;   // e.g. "stretch drape"
    std::string measure; // what value is, e.g. "max l/l0 - 1"
    double value = 0.0;
    double bound = 0.0;
    bool atMost = true; // pass if value <= bound (else: value >= bound)
    std::string unit;   // for printing: "%", "g", "s", "m", "J", "deg", "mm"
    bool pass() const { return atMost ? value <= bound : value >= bound; }
};

struct FidelityOptions {
    bool quick = false; // shorter runs, for CI and the stop hook
    std::string integrator = "xpbd";
    Material material;
    int substeps = 0; // "xpbd": 0 keeps the default
    // The jacobi family: gravity outside the implicit filter (the editor's setting).
    bool gravityOutsideFilter = false;
    bool selfContact = true; // "xpbd": the layers touch
};

std::vector<FidelityRow> runFidelity(const FidelityOptions& options);

// Peirce's cantilever: the tip-chord angle (radians) of a strip of overhang `length`
// whose bending length is c = (D / w)^(1/3), from l/c = (8 tan θ / cos(θ/2))^(1/3).
double peirceAngle(double length, double bendingLength);

// Greenhill's column of bending length c = (D / ρg)^(1/3): the height above which a strip
// clamped upright buckles under its own weight, 1.986 c; and the tip-chord angle from
// the vertical (radians) of one `height` tall whose clamp leans `lean` (radians), by
// linear theory (small deflections; it grows without bound toward the critical height).
double greenhillCriticalHeight(double bendingLength);
double greenhillTipChordAngle(double height, double bendingLength, double lean);

} // namespace pf
