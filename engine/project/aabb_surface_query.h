// The fit's surface queries answered by CGAL's AABB tree.
#pragma once

#include "project/scan_fit.h" // for meshpaint::SurfaceQueryFactory

namespace meshpaint {

//! Builds queries over triangles with CGAL's AABB tree: closest points and
//! first hits along segments in logarithmic time, whatever the scan's size,
//! and safe to call from several threads at once. Triangles without area
//! are left out (they hold no point that their neighbours do not).
SurfaceQueryFactory aabb_surface_queries();

} // namespace meshpaint
