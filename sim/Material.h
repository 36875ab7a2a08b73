#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pf {

// A paper, by physical constants (docs/material.md gives the sources). Spring and
// bending constants are derived from these and the rest geometry of each element, so
// a sheet behaves the same at any mesh resolution.
struct Material {
    std::string name = "office";
    double arealDensity = 0.080;      // kg/m² (80 g/m²)
    double stretchStiffness = 4.0e5;  // E·t, N/m (E ≈ 4 GPa, t ≈ 0.1 mm)
    double bendingStiffness = 3.0e-4; // D, N·m
    // Coulomb friction of the paper against the desk and against the tool.
    double groundStaticFriction = 0.45;
    double groundKineticFriction = 0.35;
    double toolStaticFriction = 0.8;
    double toolKineticFriction = 0.6;
    friend bool operator==(const Material&, const Material&) = default;
};

// "tissue", "office", "card"; nullptr-like empty optional is avoided: unknown → false.
bool materialPreset(std::string_view name, Material& out);
const std::vector<std::string>& materialNames();

} // namespace pf
