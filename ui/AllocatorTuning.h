#pragma once

namespace pf {

// Keeps up to 64 MB of freed memory at the top of glibc's heap instead of handing it
// back to the system after every free. The GL driver (Mesa's llvmpipe) allocates and
// frees its per-frame vertex buffers there; trimmed after each frame, their pages
// faulted in again on the next, which held a resting sheet at 10 frames per second
// under Xvfb instead of 26 (ui/README.md, "Frame rate under software GL"). Memory is
// still given back when it matters: the window calls malloc_trim(0) after New, Open
// and Reset. Blocks of 128 KB and more keep their own mappings (glibc's default; the
// setting fixes it), unmapped when freed. The editor calls this once; elsewhere it
// does nothing.
void keepFreedHeapForTheNextFrame();

} // namespace pf
