#pragma once

#include "Sheet.h"
#include "WorkerPool.h"

namespace pf {

// The tool the artist pushes with (paper Fig. 13).
struct SphereTool {
    Vec3 center{0.0, 1.0, 0.0};
    Vec3 velocity = Vec3::Zero();
    double radius = 0.03;
    bool active = false; // it touches the paper
    // Shown where the cursor is while no button is pressed, touching nothing: the
    // editor's tool before and between strokes. A hovering sphere that touched the paper
    // swept through it whenever the cursor crossed a fold or a crumpled sheet (a user's
    // three zigzags over tissue, no button pressed: 728 breaks, and nothing to undo).
    bool hovering = false;
};

// Vertices inside the sphere are moved to its surface and lose their inward velocity
// relative to it; `keepTangential` (0..1) is the share of tangential velocity kept.
// Each vertex on its own: the pool's threads share them.
void collideSphere(Sheet& sheet, const SphereTool& sphere, double keepTangential,
                   WorkerPool& pool = WorkerPool::serial());

// Same for the ground plane y = height.
void collideGround(Sheet& sheet, double height, double keepTangential,
                   WorkerPool& pool = WorkerPool::serial());

} // namespace pf
