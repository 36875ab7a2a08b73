#include "GlFunctions.h"

namespace pf {

bool GlFunctions::load(const GlProcResolver& resolve, std::string* missing) {
#define PF_GL_LOAD(type, name)                                                                     \
    name = reinterpret_cast<type>(resolve("gl" #name));                                            \
    if (!name) {                                                                                   \
        if (missing) *missing = "gl" #name;                                                        \
        return false;                                                                              \
    }
    PF_GL_FUNCTIONS(PF_GL_LOAD)
#undef PF_GL_LOAD
    return true;
}

} // namespace pf
