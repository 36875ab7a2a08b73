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
    // Curvature beyond which bending is plastic (1/m): the fibres at the surface yield
    // at a strain ε_y ≈ 0.5 %, κ_y = 2 ε_y / t. Bent further, paper keeps the extra
    // curvature when let go (a fold stays); 100/m is a 1 cm radius at t = 0.1 mm.
    double yieldCurvature = 100.0;
    // The finest crease spacing the paper forms (m): a break inserts no vertex whose new
    // edges would be shorter in the material. A sharp crease is a few thicknesses wide,
    // so about 15 thicknesses (docs/model.md, Breaking); it bounds the mesh's refinement.
    double creaseSpacing = 0.0015;
    // Coulomb friction of the paper against the desk and against the tool.
    double groundStaticFriction = 0.45;
    double groundKineticFriction = 0.35;
    double toolStaticFriction = 0.8;
    double toolKineticFriction = 0.6;
    // The sheet's thickness (m): how far apart two layers of it lie when they touch.
    double thickness = 1.0e-4;
    // Coulomb friction of the paper against itself, where its layers touch.
    double paperStaticFriction = 0.5;
    double paperKineticFriction = 0.4;
    friend bool operator==(const Material&, const Material&) = default;
};

// "tissue", "office", "card"; nullptr-like empty optional is avoided: unknown → false.
bool materialPreset(std::string_view name, Material& out);
const std::vector<std::string>& materialNames();

} // namespace pf
