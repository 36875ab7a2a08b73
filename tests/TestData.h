#pragma once

#include "World.h"

#include <optional>

namespace pf::test {

// A saved state packed in tests/data (tests/data/README.md), loaded as the editor would;
// nothing if it cannot be read.
std::optional<World> packedState(const char* name);

} // namespace pf::test
