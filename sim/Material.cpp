#include "Material.h"

namespace pf {

bool materialPreset(std::string_view name, Material& out) {
    Material m;
    if (name == "office") {
        // defaults above
    } else if (name == "tissue") {
        m.name = "tissue";
        m.arealDensity = 0.020;      // 20 g/m²
        m.stretchStiffness = 5.0e4;  // E ≈ 1 GPa, t ≈ 0.05 mm
        m.bendingStiffness = 1.2e-5; // E t³ / 12(1 − ν²)
        m.yieldCurvature = 200.0;    // 2 ε_y / t
        m.creaseSpacing = 0.00075;   // 15 t
        m.groundStaticFriction = 0.5;
        m.groundKineticFriction = 0.4;
        m.thickness = 5.0e-5;
        m.paperStaticFriction = 0.6;
        m.paperKineticFriction = 0.5;
    } else if (name == "card") {
        m.name = "card";
        m.arealDensity = 0.250;      // 250 g/m²
        m.stretchStiffness = 1.2e6;  // E ≈ 4 GPa, t ≈ 0.3 mm
        m.bendingStiffness = 1.0e-2; // E t³ / 12(1 − ν²)
        m.yieldCurvature = 33.0;     // 2 ε_y / t
        m.creaseSpacing = 0.0045;    // 15 t
        m.groundStaticFriction = 0.4;
        m.groundKineticFriction = 0.3;
        m.thickness = 3.0e-4;
        m.paperStaticFriction = 0.4;
        m.paperKineticFriction = 0.3;
    } else {
        return false;
    }
    out = m;
    return true;
}

const std::vector<std::string>& materialNames() {
    static const std::vector<std::string> names{"tissue", "office", "card"};
    return names;
}

} // namespace pf
