// The atlas as an ordinary quad mesh: each stored copy of a patch-side or
// patch-corner vertex merged into one vertex.
#pragma once

#include "atlas/atlas_topology.h"
#include "atlas/patch_layout.h"
#include "mesh/welded_surface.h"

#include <vector> // for std::vector

namespace meshpaint {

//! Welded vertex of every texel of the level (patch-major order).
//! Order: level-1 vertices, then patch-side texels edge by edge, then patch
//! interiors patch by patch.
std::vector<int> weld_map(const AtlasTopology& topology, const LevelLayout& layout);

//! Gathers texels into the welded surface; `normals` may be null.
WeldedSurface weld(const AtlasTopology& topology, const LevelLayout& layout,
                   const std::vector<Float4>& positions, const std::vector<Float4>* normals);

class Atlas;

//! The atlas's level (after subdivide()) as a welded surface; with `limit`,
//! limit positions and normals of the atlas's finest level instead.
WeldedSurface level_surface(Atlas& atlas, int level, bool limit);

} // namespace meshpaint
