#pragma once

#include "PaperState.h"
#include "Types.h"

#include <array>
#include <vector>

namespace pf {

enum class SpringKind : std::uint8_t {
    Structural = 0, // a triangle edge
    Bending = 1,    // across an interior edge of the initial mesh, between r and l
    Crease = 2,     // what a broken structural spring becomes: remembers the damage
    Hinge = 3,      // r-l spring inserted when a fold closes: remembers the fold
};
inline constexpr int kSpringKindCount = 4;

// Positions far beyond this distance from the origin (metres) count as a blow-up.
inline constexpr double kDivergenceRadius = 1.0e3;
// So does a structural spring stretched to more than this many times its rest length,
// in an integrator that bounds stretch (Integrator::boundsStretch). A blow-up can leave
// every vertex within reach: one symplectic step of a crumpled office sheet from rest
// stretched it 6,586 times over 22 m, and it was that state, a step before the one that
// went 1 km out, that was kept as "the last good state". Backward Euler stretched the
// scenes by 161 % at most (`press`), xpbd by 1 %.
inline constexpr double kDivergenceStretch = 11.0;
// ...and by more than this (metres): a crease's finely broken cells, 1-2 mm across, can
// stretch many times over for a step where a fold crosses them (8,500 % once, before the
// carry turned in the paper's plane), which is damage, not a blow-up.
inline constexpr double kDivergenceStretchReach = 0.1;
// ...and more than this many times as long as the step found it: a blow-up grows by
// orders of magnitude a step (0.19 % to 658,500 % in one), where paper already stretched
// past the limit (a jacobi sheet handed to another integrator, say) only comes back.
inline constexpr double kDivergenceGrowth = 2.0;

// Per-vertex data, structure of arrays.
struct Vertices {
    std::vector<Vec3> x;              // position
    std::vector<Vec3> v;              // velocity
    std::vector<double> m;            // lumped mass
    std::vector<Vec2> X;              // material (flat rest) coordinate
    std::vector<std::uint8_t> pinned; // 1: moved by the scene script, not by forces

    Index size() const { return static_cast<Index>(x.size()); }
};

// Per-spring data, structure of arrays.
struct Springs {
    std::vector<Index> a, b;
    std::vector<double> rest;
    std::vector<SpringKind> kind;
    std::vector<std::uint8_t> breakable;
    // Structural springs: whether a hinge was inserted across this edge already.
    std::vector<std::uint8_t> hinged;
    // Structural springs: the (up to) two triangles sharing the edge; kNone on the boundary.
    std::vector<std::array<Index, 2>> faces;
    // Crease and hinge springs: the event in the log that created them (the paper's
    // "pointers" from the auxiliary spring that make recovery possible); else kNone.
    std::vector<Index> event;
    // The largest contraction 1 - l/l0 the spring has carried since it was made. Eq. 10
    // draws only while it grows (docs/model.md, Breaking): paper damages under a load
    // beyond any it has carried before, not under one it merely goes on carrying.
    std::vector<double> peakContraction;

    Index size() const { return static_cast<Index>(a.size()); }
};

// Edge k of a triangle joins v[k] and v[(k + 1) % 3] and is spring e[k].
struct Triangle {
    std::array<Index, 3> v{kNone, kNone, kNone};
    std::array<Index, 3> e{kNone, kNone, kNone};
    friend bool operator==(const Triangle&, const Triangle&) = default;
};

enum class EventKind : std::uint8_t { Break = 0, Hinge = 1 };

// One entry of the chronological damage log. Everything recovery needs is here.
struct DamageEvent {
    EventKind kind = EventKind::Break;
    bool active = true;    // false once recovered
    std::int64_t step = 0; // simulation step at which it happened
    Index edge = kNone;    // Break: e_ij (now a crease). Hinge: the hinged edge.
    Index vertex = kNone;  // Break: the inserted vertex n
    std::array<Index, 4> springs{kNone, kNone, kNone, kNone}; // Break: e_in, e_nj, e_rn, e_nl.
                                                              // Hinge: springs[0] is the hinge.
    std::array<Index, 4> tris{kNone, kNone, kNone, kNone};    // Break: triangles after the split
    std::array<Triangle, 2> oldTris{};                        // Break: the two replaced triangles
    std::array<Triangle, 4> newTris{};                        // Break: what tris[] held when made
    std::array<double, 2> massTaken{0.0, 0.0};                // Break: mass moved from i, j to n
};

struct Sheet {
    Vertices verts;
    Springs springs;
    std::vector<Triangle> tris;
    std::vector<DamageEvent> events;
    PaperState paper;
    double density = 0.08; // kg/m^2 (80 g/m^2 paper)

    Index triangleCount() const { return static_cast<Index>(tris.size()); }

    // Appends a spring and returns its id.
    Index addSpring(Index a, Index b, double rest, SpringKind kind, bool breakable);
    // Appends a vertex and returns its id.
    Index addVertex(const Vec3& x, const Vec3& v, double m, const Vec2& X);

    // The vertex of triangle t that is not on edge (a, b).
    Index oppositeVertex(Index t, Index a, Index b) const;
    // Position (0..2) of edge (a, b) in triangle t, in either direction, or -1.
    int edgeSlot(Index t, Index a, Index b) const;

    // Material (rest) length between two vertices.
    double materialDistance(Index a, Index b) const { return (verts.X[a] - verts.X[b]).norm(); }

    // Reserve room so that breaks within a step do not reallocate every time.
    void reserveFor(Index extraVertices);
};

} // namespace pf
