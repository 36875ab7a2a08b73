#pragma once

#include <string>

namespace pf {

// What the compiler was allowed to assume about the processor, for the speed a
// benchmark reports: "portable (x86-64 baseline: SSE2)" for the default build, which
// runs on any x86-64; "native (...)" with the vector extensions it used when built with
// -DPAPERFOLD_NATIVE=ON (-march=native), which runs only on processors like the one
// that built it.
std::string buildTuning();

} // namespace pf
