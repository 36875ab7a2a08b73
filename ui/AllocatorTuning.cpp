#include "AllocatorTuning.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace pf {

void keepLargeAllocationsReturnable() {
#if defined(__GLIBC__)
    // Setting the threshold explicitly also turns off glibc's dynamic adjustment of it.
    mallopt(M_MMAP_THRESHOLD, 256 * 1024);
#endif
}

} // namespace pf
