// A mesh file's own colours carried onto a fresh painting surface as its
// diffuse channel.
#pragma once

#include "paint/paint_surface.h"

namespace meshpaint {

//! When the surface's base mesh has colours (BaseMesh::colours), refines
//! them by Catmull-Clark's rules to the painting level (as OpenSubdiv
//! interpolates any vertex data) and sets them as the diffuse channel; does
//! nothing otherwise. Not a stroke: no undo step.
void apply_imported_colours(PaintSurface& surface);

} // namespace meshpaint
