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

} // namespace pf::test
