// Launch ranges of kernels over an atlas level: the grid argument they
// address a level by, and work items per texel of whole tiles or interiors.
#pragma once

#include "atlas/patch_layout.h"
#include "cl/opencl.h"

#include <utility> // for std::pair

namespace meshpaint {

//! The (tile, tiles_x) pair kernels take to address a level.
inline cl_int2 grid(const LevelLayout& l) { return cl_int2{{l.tile, l.tiles_x}}; }

//! Global and local range for `count` whole tiles of a level, a work item per
//! texel: (tile, tile * count).
std::pair<cl::NDRange, cl::NDRange> range_tiles(const LevelLayout& layout, int count);
//! The same for the texels strictly inside the tiles (interior_texel() in
//! atlas_access.cl): (n - 1, (n - 1) * count). Levels from 2 on.
std::pair<cl::NDRange, cl::NDRange> range_interiors(const LevelLayout& layout, int count);

} // namespace meshpaint
