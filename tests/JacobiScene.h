#pragma once

#include "Scenes.h"

#include <string_view>

namespace pf::test {

// A scene stepped by the paper's own integrator (Eq. 6, one Jacobi sweep). The tests of
// the break-and-recover machinery use it because its soft springs compress and break as
// soon as a tool pushes a free sheet; the default xpbd's paper slides ahead of the tool
// across the desk, as real paper does, and breaks only where something holds it
// (docs/material.md). The machinery under test is the same for both.
inline World jacobiScene(std::string_view name, const SceneOptions& options = {}) {
    World w = *makeScene(name, options);
    w.params.integrator = "jacobi";
    return w;
}

// The scene in the integrator the build can afford, for tests of machinery that is the
// same for every integrator (undo, replay, resume, scripts, the Fold tool's carry): the
// default, xpbd, in Release; jacobi under the sanitizers, where xpbd's 40 sub-steps made
// the sanitized suites 3-4 times slower (CI went from 28 to 48 minutes).
inline World machineryScene(std::string_view name, const SceneOptions& options = {}) {
    World w = *makeScene(name, options);
    if (PAPERFOLD_TEST_SLOWDOWN > 1) w.params.integrator = "jacobi";
    return w;
}

} // namespace pf::test
