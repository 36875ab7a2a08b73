#pragma once

#include "Sheet.h"

namespace pf {

// Removal of single elements by moving the last element into the hole, then renaming
// every reference to the moved element (triangles, spring faces, active log events).
// Removing the newest element moves nothing, so undoing the newest change restores
// the arrays bit for bit. The caller must have dropped all references to the element.
void removeSpringAt(Sheet& sheet, Index s);
void removeTriangleAt(Sheet& sheet, Index t);
void removeVertexAt(Sheet& sheet, Index v);

// Puts `to` where `from` is in a spring's face pair.
void replaceFace(Sheet& sheet, Index spring, Index from, Index to);
// Puts t in the first free slot of a spring's face pair.
void attachFace(Sheet& sheet, Index spring, Index t);

} // namespace pf
