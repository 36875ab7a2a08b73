#pragma once

#include "Integrator.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <vector>

namespace pf {

// Paper as it is: nearly inextensible, softly bending. Each step has two parts.
// 1. Bending, implicitly: the material's D gives one linear stencil per interior edge
//    (the isometric bending model of Bergou et al. 2006: its energy is quadratic in the
//    positions), so backward Euler for bending is one solve with a constant matrix
//    M + (h² + βh) Q, factored once per topology (sparse LDLᵀ) and reused every step.
//    An explicit or iterated bending constraint cannot hold card stock up at all.
// 2. Stretch and contact, by extended position-based dynamics with sub-steps (Macklin
//    et al. 2019, "Small steps in physics simulation"): params.substeps sub-steps, each
//    with gravity, a forward and a backward Gauss-Seidel pass over the distance
//    constraints whose stiffness comes from E·t, and the desk and the tool with Coulomb
//    friction at position level.
// docs/model.md gives where this departs from the paper.
class XpbdIntegrator final : public Integrator {
  public:
    void advance(Sheet& sheet, const SimParams& params) override;
    bool resolvesContacts() const override { return true; }
    void setContacts(const ContactScene& scene) override { contacts_ = scene; }
    bool asleep() const override { return asleep_; }

    // One term ½ |Σ k x|² / compliance of the bending energy: a second difference of
    // the positions (Σ k = 0 and Σ k X = 0, so it vanishes on the flat rest sheet).
    struct Stencil {
        std::array<Index, 5> v{};
        std::array<double, 5> k{};
        int count = 0;
        double compliance = 0.0;
    };
    // The stretch stiffness of each spring (N/m) and the bending stencils the solver
    // uses for this sheet; exposed for tests.
    static std::vector<double> stretchStiffness(const Sheet& sheet, const Material& m);
    static std::vector<Stencil> bendingStencils(const Sheet& sheet, const Material& m);

  private:
    void rebuild(const Sheet& sheet, const SimParams& params);
    void factor(const Sheet& sheet, const SimParams& params);
    void colourStretchConstraints(Index vertices);
    void bendImplicitly(Sheet& sheet, const SimParams& params, const Vec3& g);
    bool shouldSleep(const Sheet& sheet) const;
    bool mustWake(const Sheet& sheet) const;

    ContactScene contacts_;
    std::array<std::int64_t, 7> signature_{-1, -1, -1, -1, -1, -1, -1};
    Material builtFor_;
    std::vector<double> compliance_; // per spring; < 0: not a stretch constraint
    std::vector<double> maxPush_;    // per spring: compressive force before buckling, N
    std::vector<Stencil> stencils_;
    // The stretch constraints packed for the sub-step loop, ordered by colour.
    struct StretchConstraint {
        Index a, b;
        double rest, compliance, maxPush;
    };
    std::vector<StretchConstraint> stretch_;
    struct Tether {
        Index vertex, pin;
        double length; // material distance: the paper between them, unstretched
    };
    std::vector<Tether> tethers_;
    Eigen::SparseMatrix<double> bending_; // Q: E_bend = ½ Σ_c xᵀ Q x over coordinates c
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
    std::vector<double> solveMass_; // M of the solve: pinned vertices made immovable
    double factoredDt_ = 0.0, factoredDamping_ = -1.0;
    bool factored_ = false;
    Eigen::MatrixXd rhs_, sol_;
    std::vector<Vec3> xPrev_;
    std::vector<double> w_;             // inverse masses, 0 for pinned vertices
    std::vector<std::uint8_t> touched_; // held by the tool in this sub-step
    int quietSteps_ = 0;
    bool asleep_ = false;
};

// Poisson's ratio of the plate bending energy (paper: 0.2-0.4).
inline constexpr double kPoisson = 1.0 / 3.0;
// Bending left across the edges of a crease (around a vertex a break inserted), as a
// share of the sheet's: a crease is a line where the paper has given way.
inline constexpr double kCreaseBendingShare = 0.02;
// A sheet whose every free vertex stays slower than 0.5 mm/s this many steps in a row,
// with no tool moving near it and no pinned vertex moving, falls asleep.
inline constexpr int kStepsBeforeSleep = 30;
// How far beyond its surface the tool grips the paper (m).
inline constexpr double kToolReach = 0.001;

} // namespace pf
