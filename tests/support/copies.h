// Checks on the atlas's stored copies of patch-side and corner texels.
#pragma once

#include "atlas/atlas_topology.h"
#include "atlas/patch_layout.h"
#include "core/vec.h"

#include <vector> // for std::vector

namespace meshpaint::test {

//! Texels whose bits differ from the first stored copy of the same vertex
//! (0 when every copy is identical).
std::size_t differing_copies(const AtlasTopology& topology, const LevelLayout& layout,
                             const std::vector<Float4>& texels);

} // namespace meshpaint::test
