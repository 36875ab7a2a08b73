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

// Whether tests of machinery that is the same for every integrator (undo, replay, resume,
// scripts, the tools, the command line's files) step their sheets in jacobi rather than
// the default xpbd: under the sanitizers, where xpbd's 40 sub-steps made the sanitized
// suites 3-4 times slower (CI went from 28 to 48 minutes). Release runs the default.
inline constexpr bool kMachineryInJacobi = PAPERFOLD_TEST_SLOWDOWN > 1;

// `w` in the integrator the build can afford for such tests (kMachineryInJacobi).
inline void affordMachinery(World& w) {
    if (kMachineryInJacobi) w.params.integrator = "jacobi";
}

inline World machineryScene(std::string_view name, const SceneOptions& options = {}) {
    World w = *makeScene(name, options);
    affordMachinery(w);
    return w;
}

} // namespace pf::test
