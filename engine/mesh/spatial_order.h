// Reordering a mesh so that faces near in space are near in memory.
#pragma once

#include "mesh/base_mesh.h"

#include <vector> // for std::vector

namespace meshpaint {

//! The same surface with faces sorted along a Morton (Z-order) curve through
//! their centroids and vertices numbered in order of first use. Patches of
//! the atlas follow face order, so neighbouring patches share cache lines
//! and pages, which the table-driven kernels depend on for speed.
//! `face_order[k]` is the input face that became face k.
BaseMesh spatially_ordered(const BaseMesh& mesh, std::vector<int>* face_order = nullptr);

} // namespace meshpaint
