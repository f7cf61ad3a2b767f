// A mesh file's own colours and channel values carried onto a fresh
// painting surface as its channels.
#pragma once

#include "paint/paint_surface.h"

namespace meshpaint {

//! When the surface's base mesh has colours (BaseMesh::colours) or other
//! channel values (BaseMesh::channels), refines each by Catmull-Clark's rules
//! to the painting level (as OpenSubdiv interpolates any vertex data,
//! refined_to_painting_level()) and sets it as its channel (colours as
//! diffuse), clamped to 0-1 but for displacement; does nothing otherwise.
//! Not a stroke: no undo step.
void apply_imported_channels(PaintSurface& surface);

} // namespace meshpaint
