#pragma once

#include "Integrator.h"
#include "ProjectionSystem.h"
#include "SelfContact.h"
#include "StretchPass.h"
#include "SymmetricAmdOrdering.h"
#include "VectorLdlt.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace pf {

// Poisson's ratio of the plate bending energy (paper: 0.2-0.4).
inline constexpr double kPoisson = 1.0 / 3.0;
// Bending left across the edges of a crease (around a vertex a break inserted), as a
// share of the sheet's: a crease is a line where the paper has given way.
inline constexpr double kCreaseBendingShare = 0.02;
// A sheet whose every free vertex moves no more than 0.5 mm/s × dt over each of this
// many steps in a row, with no tool moving near it and no pinned vertex moving, falls
// asleep.
inline constexpr int kStepsBeforeSleep = 30;
// So does one whose every free vertex's mean position (kStillAveraging) stays within
// kStillReach of where it was for this long: a drift of 0.5 mm/s at most, and a jitter
// of about two pixels where the editor's default view shows the sheet.
inline constexpr double kSecondsStillBeforeSleep = 1.0;
inline constexpr double kStillReach = 5e-4; // m
// The still rule reads each vertex's position averaged over the steps, the latest
// weighing this much (about the last eight): a cycle of a few steps then reads as the
// place it goes round. Read on the positions themselves, a sheet folded twice whose
// crossing creases cycled through four steps 0.57 mm apart never fell asleep and cost
// 9 ms a step for as long as it was left (docs/material.md, "Sleep").
inline constexpr double kStillAveraging = 0.125;
// ... and, read alongside, averaged over about the last 128 steps (half a second): a
// pinned, crumpled card swung one vertex 0.9 mm up and down, and the paper round it less,
// in a cycle of 264 steps (1.1 s) for as long as it was left, costing 15-31 ms a step
// (a helper's editor session, 2026-12-01); its mean over eight steps spans 0.80 mm,
// over 128 0.10 mm. Read on this average alone, a tissue sheet folded twice
// slept 6 s later than on the other (its mean lags the settling after the let-go), so
// the sheet sleeps when either has stayed put.
inline constexpr double kSlowStillAveraging = 1.0 / 128.0;
// How far below its surface the tool grips the paper it presses onto the desk (m).
inline constexpr double kToolReach = 0.001;
// The bending solve runs every this many sub-steps, over their time together. Its step
// must stay short: solved once per step (h = 1/240 s), the bending that stretch
// constraints held back came back each step as a velocity kick of up to 0.5 m/s, the
// sheet never came to rest, and the jitter pushed a 10 cm cantilever past the yield
// curvature (+48 %). Every sub-step works too but costs 1.7 times more; every 8th of 20
// (h = 1/1200 s) still let the cantilever yield.
inline constexpr int kSubstepsPerBendingSolve = 4;
// Bends at least this wide (a stencil's span) get the whole Rayleigh damping β; a
// narrower one gets β (span / kFullyDampedSpan)², so that a cell's own bend is damped
// as much relative to its frequency (ω ∝ 1/span²) at any resolution. With β whole on
// every stencil, a 2.5 mm cell's bends were some 6,500 times their mass in one solve,
// pulled back only h_b/β of the way while the stretch passes pushed them out in every
// sub-step: a column standing at 0.8 of Greenhill's height folded at its foot, and
// a crumpled sheet of 4 mm cells kept a sub-step cycle until the still rule stopped
// it (docs/material.md, "Bending damping per cell"). 8 mm leaves the editor's 11.7 mm
// cells as they were.
inline constexpr double kFullyDampedSpan = 0.008; // m
// Fast projection after the sub-steps: Newton iterations, the largest stretch the
// sub-steps may leave before it runs, and its compliance relative to the constraints'
// inverse masses (a triangle mesh held by pins has more edges than free directions).
// A Newton step of the projection that multiplies the worst stretch by more than this
// diverges: it is halved, up to kProjectionHalvings times before the projection stops
// (at the least stretched state it reached).
inline constexpr double kProjectionDivergence = 2.0;
inline constexpr int kProjectionHalvings = 4;
inline constexpr double kProjectedStretch = 3e-3;
// The projection couples every two constraints that meet at a vertex, so a vertex with
// d of them puts a dense d × d block into J W Jᵀ. Paper's vertices have at most 35
// springs of any kind (a sheet folded three times, crumple-cycles after 20 s); a
// recording the fuzzer made broke a 58 m edge into a fan of 1,867 springs round one
// vertex, and each factorisation took a second. Past this many stretched edges at a
// free vertex the step is left to the sub-steps.
inline constexpr int kMaxProjectedDegree = 64;
inline constexpr double kProjectionCompliance = 1e-3;
// Where paper (a material at least as stiff as kPaperStiffness) hangs from
// pins that stand still or from the hand, with the tool out of it, the compliance is this
// instead, and it damps the Newton step (Levenberg-Marquardt). A triangle mesh has more
// edges than free directions, so J W Jᵀ is nearly singular wherever the sheet is flat,
// and the undamped step overshot along those directions: each Newton iteration left the
// worst stretch at a median 0.64 of what it was, a corner held up by the hand took 2.6
// iterations a step, a drape at resolution 30 took 3.5 and one at 40 up to 16 (all it
// then might), each with its own ordering and factorisation. At 0.02 both held sheets take
// about one (test_paper_behaviour). docs/speed.md has the times, the values tried and
// why the damping is kept out of free sheets, the tool and pins that move.
inline constexpr double kDampedProjectionCompliance = 0.02;
// The fast projection, damped or not, is for paper (E·t, N/m; tissue is 5·10⁴): it
// pulls every stretched edge back to its rest length and gives the vertices that move's
// velocity, and a sheet much softer, stretched again by its own weight every step, was
// pumped by it. The stability map's hanging sheet at 100 N/m (its ×1) blew up in 8 of
// the 12 resolutions and steps around the map's cell, at 1,000 N/m in 2 (undamped; damped
// at 0.03 in all 12 and in 3); at 10⁴ and 5·10⁴ N/m, damped at 0.02, in none (docs/speed.md,
// docs/solver-lab.md). A softer material is left to the sub-steps, whose compliance
// gives it the stretch its stiffness implies.
inline constexpr double kPaperStiffness = 1e4;
// From the fourth damped Newton iteration of a projection on, one that leaves more than
// this share of the worst stretch it started from ends the damping for the rest of it:
// between the still pins of a crumpled sheet the damped iterations crawled (0.96 of the
// worst each) and the sixteenth left 0.9 %. An earlier or a stricter switch took the
// damping from the hanging `drape` too (1.2-1.5 iterations a step instead of 1.07).
inline constexpr double kSlowDampedProgress = 0.9;
inline constexpr int kDampedIterationsBeforeFallback = 3;
// Newton iterations of the projection (it stops once the worst stretch is
// kProjectedStretch). Where pins or the tool's grip hold the paper the tension between
// them is set by where they hold it, and the sub-steps leave much of it (a sheet pinned
// at its four corners and lifted by its middle: 2.6-8.7 % stretch after them; four
// iterations left it 4.7 %, it takes 6-13). A free sheet once kept four, but at the
// let-go of a second fold across a first the slivers its breaks inserted (0.5 mg
// vertices) jumped to 52 % stretch and stayed 2-28 % for many steps (2.2 % two seconds
// later); sixteen left those at most 0.3 %, and a settled sheet stops after one.
inline constexpr int kProjectionIterations = 16;
// Past kProjectionIterations the projection goes on, up to this many in all, while the
// worst stretch is over the bound paper must keep (issue 9: 1 %, kStretchBound): where
// crumple-cycles gathers the sheet its sub-steps left up to 68 % on a crease's light
// vertices, and one step ended its sixteenth iteration at 14 % (seed 2 at 7.85 s).
inline constexpr int kMaxProjectionIterations = 48;
static_assert(kProjectionIterations <= kMaxProjectionIterations);
inline constexpr double kStretchBound = 0.01;
// Where Newton's projection ends over kStretchBound (nearly dependent edges round
// vertices of a tenth of a milligram, where its steps wander: tissue's crumple-cycles
// ended all 48 iterations at 8.3 % on a 1.04 mm edge between 0.098 and 0.065 mg), up to
// this many Gauss-Seidel sweeps pull the stretched edges it holds toward their rest
// lengths, and Newton starts once more from there. Each edge's |d| ≤ rest is a convex
// set and a sweep projects onto them one after another, so the sweeps cannot wander as
// Newton does; but they carry a pull one edge a sweep, and alone took about 600 sweeps
// to bring the worst edge to 1 % there (64 left 2.75 %). Newton from where 64 left it
// ended at 0.26 % in 5 iterations.
inline constexpr int kLeftoverSweeps = 64;
// Where Newton wanders from that second start as well, the sweeps go on alone, up to
// this many: they cannot wander, and a rare step pays for them (tissue's crumple-cycles,
// once the plate's sum stencils yielded as the others do, ended a step at 3.1 % after
// both starts).
inline constexpr int kStubbornSweeps = 4096;
// An edge shorter than its rest length by more than this has buckled (the sub-steps
// cap its push at the buckling load) and is left out of the projection; every other
// edge is held at its rest length, as paper below its buckling load is.
inline constexpr double kBuckledStrain = 1e-5;
// Self-contact looks for the layers a vertex may meet this much farther than twice its
// travel in a step (m): room for what the constraints move it besides.
inline constexpr double kContactMargin = 5e-4;
// ... but no farther than this (m): paper flung at tens of metres a second by a step that
// went wrong asked for 450,000 pairs. Paper faster than this per step (4.8 m/s at
// h = 1/240 s) may pass through a layer it was not near when the step began.
inline constexpr double kMaxContactAllowance = 0.02;
// Layers that a sub-step begins inside each other's thickness part at most this fast
// (m/s): 0.4 mm a step.
inline constexpr double kContactSeparationSpeed = 0.1;
// Paper closer than this many crease spacings to a vertex in the material is its own
// layer bending, not another layer it could touch: the creases and hinges keep it.
inline constexpr double kContactApart = 3.0;
// Halvings of a step's move in which the tool stops short of paper drawn taut: a step
// moves it at most EditSession::kMaxToolSpeed · dt (6 mm at 1/240 s), found to 6 µm.
inline constexpr int kToolHoldBisections = 10;
// Compliance of the tool's grip (m/N): a millimetre of slack per newton.
inline constexpr double kGripCompliance = 1e-3;
// A hand that grabs the paper holds its vertex by a grip of the same compliance and pulls
// with at most this force (N), a pinch between finger and thumb: paper pulled harder
// slips out of it. Held rigidly, the hand tore paper pinned at its corners apart (a
// 40 px drag upward in the editor: 306 breaks, 454 % strain).
inline constexpr double kHandForce = 2.0;

// Paper as it is: nearly inextensible, bending softly and plastically past its yield.
// A step is params.substeps sub-steps of extended position-based dynamics (Macklin et
// al. 2019, "Small steps in physics simulation"), then a fast projection:
// 1. Bending and gravity, implicitly, every kSubstepsPerBendingSolve sub-steps: the
//    material's D gives plate-bending stencils whose energy is quadratic in the
//    positions (as in the isometric model of Bergou et al. 2006), so backward Euler is
//    one solve with a constant matrix M + (h² + βh) Q, factored once per topology. An
//    explicit or iterated bending constraint could not hold card stock up at all. Each
//    stencil keeps a plastic rest value that follows it past the yield curvature.
// 2. In each sub-step: the desk and the tool with Coulomb friction (the tool's grip a
//    soft, force-limited constraint), a forward and a backward Gauss-Seidel pass over
//    the distance constraints from E·t (their push capped at the buckling load),
//    tethers to the pins, and the contacts again without friction.
// 3. When the sub-steps leave an edge stretched by more than 0.3 %, a fast projection of
//    every structural edge not buckled back to its rest length.
// The plastic rest values are updated once per step, before the first bending solve.
// docs/model.md and docs/material.md give where this departs from the paper and why.
class XpbdIntegrator final : public Integrator {
  public:
    void advance(Sheet& sheet, const SimParams& params) override;
    bool resolvesContacts() const override { return true; }
    void setContacts(const ContactScene& scene) override { contacts_ = scene; }
    bool asleep() const override { return asleep_; }
    std::optional<Vec3> toolHeldAt() const override { return toolHeldAt_; }
    // The fast projection's work since this integrator was made: Newton iterations that
    // factored their system (each with its own ordering, factorisation and solve).
    struct ProjectionWork {
        std::int64_t newtonIterations = 0;
    };
    ProjectionWork projectionWork() const { return projectionWork_; }

    // One term ½ |Σ k x|² / compliance of the bending energy: a second difference of
    // the positions (Σ k = 0 and Σ k X = 0, so it vanishes on the flat rest sheet).
    struct Stencil {
        std::array<Index, 5> v{};
        std::array<double, 5> k{};
        int count = 0;
        double compliance = 0.0;
        // Σ k x per unit curvature (1/m) of a cylindrical bend of the rest sheet, in the
        // direction the stencil reads most: 1 for a second difference along a grid line
        // and for their sum, ½ for the mixed one (a diagonal bend); converts the yield
        // curvature into this stencil's measure.
        double unit = 0.0;
        // Half the widest span of the stencil in the material: the length over which its
        // curvature stands for a turn of the paper (a cell, for a grid stencil).
        double span = 0.0;
    };
    // The stretch stiffness of each spring (N/m) and the bending stencils the solver
    // uses for this sheet; exposed for tests.
    static std::vector<double> stretchStiffness(const Sheet& sheet, const Material& m);
    static std::vector<Stencil> bendingStencils(const Sheet& sheet, const Material& m);

  private:
    // The step the bending solve is factored for: kSubstepsPerBendingSolve sub-steps.
    static double solveStep(const SimParams& p) {
        const int n = std::max(1, p.substeps);
        return std::min(kSubstepsPerBendingSolve, n) * p.dt / n;
    }
    void rebuild(Sheet& sheet, const SimParams& params);
    void factor(const Sheet& sheet, const SimParams& params);
    void colourStretchConstraints(Index vertices);
    void bendImplicitly(Sheet& sheet, const Vec3& g, double h);
    void yieldPlastically(Sheet& sheet, const Material& m);
    void projectStretch(Sheet& sheet, double dt, int iterations, double compliance);
    void relaxWhatTheProjectionLeft(Sheet& sheet, double dt, int sweeps);
    // Pushes the paper out of the tool at the end of the step, and stops the tool short
    // (toolHeldAt_) where that would stretch taut paper; `from` is where it began, and
    // paper that lies in the tool there pushes it back behind it.
    void holdToolWhereThePaperIsTaut(const Vec3& from,
                                     const std::function<void(const Vec3&)>& pushOut,
                                     bool toolInThePaper, Sheet& sheet);
    bool retrying_ = false; // in the projection's second start (kLeftoverSweeps): no third
    struct {
        std::vector<Vec3> x, v;
    } ended_; // where the first start ended, kept in case the second does worse
    double worstProjectedStretch(const Sheet& sheet) const;
    bool mustWake(const Sheet& sheet) const;

    ContactScene contacts_;
    SelfContact selfContact_;
    std::vector<double> allowance_; // per vertex: how far it may move in this step, m
    std::array<std::int64_t, 8> signature_{-1, -1, -1, -1, -1, -1, -1, -1};
    Material builtFor_;
    std::vector<Stencil> stencils_;
    // Plastic bending: per stencil, the rest value of Σ k x (the curvature the paper
    // keeps when let go, in the stencil's measure), and the force those rest values
    // exert on each vertex in this step.
    std::vector<Vec3> plastic_, plasticForce_;
    bool anyPlastic_ = false;
    // The stretch constraints packed for the sub-step loop, ordered by colour.
    struct StretchConstraint {
        Index a, b;
        double rest, compliance;
        double maxPush, maxPull; // the largest force the constraint exerts each way, N
        int colour = 0;          // kSharedColour: shares vertices with others of it
    };
    static constexpr int kSharedColour = 63;
    std::vector<StretchConstraint> stretch_;
    // The same, as the sub-steps of one step use them (advance() says why).
    StretchPass stretchStep_;
    // The projection holds the structural edges (unlimited pull) not pinned at both ends.
    bool projects(const StretchConstraint& k) const {
        return k.maxPull == std::numeric_limits<double>::infinity() && w_[k.a] + w_[k.b] != 0.0;
    }
    struct Tether {
        Index vertex, pin;
        double length; // material distance: the paper between them, unstretched
    };
    std::vector<Tether> tethers_;
    Eigen::SparseMatrix<double> bending_; // Q: E_bend = ½ Σ_c xᵀ Q x over coordinates c
    VectorLdlt solver_;
    std::vector<double> solveMass_; // M of the solve: pinned vertices made immovable
    double factoredDt_ = 0.0, factoredDamping_ = -1.0;
    bool factored_ = false;
    std::vector<Vec3> rhs_, sol_;
    std::vector<Vec3> xPrev_;
    std::vector<Vec3> beforeTool_;      // positions before the tool's last push out
    std::optional<Vec3> toolHeldAt_;    // where the last step stopped the tool
    std::vector<Vec3> stepStart_;       // positions before this step's sub-steps
    std::vector<double> w_;             // inverse masses, 0 for pinned vertices
    std::vector<Vec3> airNormals_;      // dragThroughAir's scratch
    std::vector<std::uint8_t> touched_; // touched by the tool in this sub-step
    std::vector<std::uint8_t> onDesk_;  // held up by the desk in this step
    std::vector<double> deskImpulse_;   // what the desk pushed up on each vertex, N·s
    std::vector<Index> toolTriangles_;  // triangles the tool may reach in this step
    // Fast projection: the stretched constraints, their directions, and which of them
    // meet at each vertex.
    std::vector<std::size_t> active_;
    std::vector<Vec3> dir_;
    // Positions and velocities before the Newton step being tried.
    std::vector<Vec3> projectedFrom_, velocityFrom_;
    std::vector<Index> incidentStart_;
    std::vector<std::pair<Index, Index>> ends_; // each stretched constraint's vertices
    std::vector<ConstraintAtVertex> incident_;
    Eigen::SparseMatrix<double> projectionSystem_; // J W Jᵀ + ε, its lower triangle
    SymmetricLdlt projection_;
    ProjectionWork projectionWork_;
    std::vector<Vec3> bestX_, bestV_; // projectStretch's least stretched state
    double longestEdge_ = 0.0;        // rest length, m
    bool asleep_ = false;
    // The gravity of the last step (none before the first): a change wakes the sheet.
    std::optional<Vec3> lastGravity_;
};

} // namespace pf
