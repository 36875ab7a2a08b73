#pragma once

namespace pf {

// Makes glibc serve every allocation of 256 KB or more with its own mapping, returned
// to the system when freed. By default glibc raises that threshold after each large
// free, so the snapshots and surfaces of a crumpled sheet end up inside its arenas and
// stay there, fragmented, after File ▸ New (docs/safety.md has the measurements). The
// editor calls this once; elsewhere it does nothing.
void keepLargeAllocationsReturnable();

} // namespace pf
