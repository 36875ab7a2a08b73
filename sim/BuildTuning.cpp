#include "BuildTuning.h"

namespace pf {

std::string buildTuning() {
    std::string extensions;
    const auto add = [&](const char* name) {
        if (!extensions.empty()) extensions += ", ";
        extensions += name;
    };
#if defined(__AVX512F__)
    add("AVX-512");
#endif
#if defined(__AVX2__)
    add("AVX2");
#elif defined(__AVX__)
    add("AVX");
#endif
#if defined(__FMA__)
    add("FMA");
#endif
#if defined(__SSE4_2__) && !defined(__AVX__)
    add("SSE4.2");
#endif
    if (extensions.empty()) add("SSE2");
#if defined(PAPERFOLD_NATIVE)
    return "native (-march=native: " + extensions + ")";
#else
    return "portable (x86-64 baseline: " + extensions + ")";
#endif
}

} // namespace pf
