#pragma once

#include "Params.h"
#include "Rng.h"
#include "Sheet.h"
#include "StepWorkers.h"

#include <vector>

namespace pf {

// Eq. 10: probability that a compressed breakable spring breaks.
//   l, l0: current and rest length of e_ij; lrl = |x_r - x_l|;
//   nij = n_i·n_j, nrl = n_r·n_l; phi = fragility.
// Zero for a spring that is not compressed (Eq. 10 is only defined for l < l0).
double breakProbability(double l, double l0, double lrl, double nij, double nrl, double phi);

// Eq. 10 is read as a probability per reference growth of an edge's contraction; the
// probability of a break while the contraction grows by `growth` beyond its peak.
double breakProbabilityForGrowth(double P, double growth, double referenceGrowth);

// Eq. 11: how far the new vertex moves along the normal, h = ψ/2 sqrt(l0² - l²).
double breakOffset(double l, double l0, double psi);

// Whether Eq. 10 applies to `spring` at all: a breakable structural edge between two
// triangles (a border edge has nowhere to put the new vertex's second face).
bool canBreak(const Sheet& sheet, Index spring);

// Whether breaking `spring` would keep every new edge at least `spacing` long in the
// material: the finest crease spacing the paper forms (Material::creaseSpacing).
bool keepsCreaseSpacing(const Sheet& sheet, Index spring, double spacing);

// Sets every spring's peak contraction to the contraction it carries now, as `params`
// read it (the chord, or the arc for xpbd): a sheet made before load-driven breaking, or
// one whose integrator changes the reading, counts as having carried the load it stands
// under.
void recordCurrentContraction(Sheet& sheet, const SimParams& params);

// Breaks structural spring `spring` (which must have two faces): inserts vertex n
// between its ends, offset by Eq. 11 toward the side the edge bends to, splits both
// triangles, turns the spring into a crease and logs the event. Returns the event id.
// `keepLengths` (paper that does not stretch, keepsEdgeLengths): n is moved from Eq. 11's
// point to where none of its four new edges is longer than its rest length (or, where no
// point is, to one that shares the excess among them).
Index breakEdge(Sheet& sheet, Index spring, const std::vector<Vec3>& normals, double psi,
                std::int64_t step, bool keepLengths = false);

// §4.2 recovery condition: e_ij is still this event's crease, e_in and e_nj are still
// breakable, and the four triangles are as the break left them.
bool canRecover(const Sheet& sheet, Index event);

// Undoes a damage event (a break or a hinge). A break recovery removes n, its four
// springs, every hinge that uses n or one of those springs, restores the two
// triangles and makes e_ij breakable again with rest length |X_i - X_j|.
// Returns false (and changes nothing) when the event cannot be recovered.
bool recoverEvent(Sheet& sheet, Index event);

// Eq. 10 for `spring` as the sheet stands (`normals`: its vertex normals): zero where
// the spring cannot break, is not contracted (as `params` read it), joins two pinned vertices, or
// is too short to split (keepsCreaseSpacing).
double springBreakProbability(const Sheet& sheet, const std::vector<Vec3>& normals, Index spring,
                              const SimParams& params);

// Per-step scratch for the break pass, kept to avoid allocation in the step.
struct BreakScratch {
    std::vector<Vec3> normals;
    std::vector<Vec3> triangleNormals;
    std::vector<std::uint8_t> touched; // per triangle: changed this step
    // Per spring that existed when the pass began: Eq. 10 as the pass drew it. The
    // editor's overlay shows these rather than working Eq. 10 out a second time.
    std::vector<float> probability;
    // A spring Eq. 10 applies to, as the pass found it before any break of the pass.
    struct Candidate {
        Index spring;
        double probability;
        double contraction;
    };
    std::vector<std::vector<Candidate>> candidates; // per chunk of the springs, in order
    std::vector<std::uint8_t> massGiven;            // per vertex: gave mass to a break this pass
};

// Eq. 10 for every spring of the sheet as it stands, into scratch.probability (all zero
// when breaking is off): for a sheet changed outside a step, such as by an undo.
void computeBreakProbabilities(const Sheet& sheet, const SimParams& params, BreakScratch& scratch);

// Tests every breakable contracted spring (as params read it: the chord, or the arc for
// xpbd) with two faces in index order, at most one break per triangle per step. A spring whose
// contraction has grown past its peak draws one uniform number from rng (breakProbabilityForGrowth)
// and records the new peak. Returns the number of breaks. With workers, Eq. 10 is read on
// their threads; the draws and the breaks are made in index order on the caller's, so the
// pass gives the same bits on any number of threads.
int runBreakPass(Sheet& sheet, const SimParams& params, Rng& rng, std::int64_t step,
                 BreakScratch& scratch, const StepWorkers& workers = {});

} // namespace pf
