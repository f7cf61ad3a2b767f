// Reordering a mesh so that faces near in space are near in memory.
#pragma once

#include "mesh/base_mesh.h"

#include <cstddef> // for std::size_t
#include <vector>  // for std::vector

namespace meshpaint {

//! The same surface with faces sorted along a Morton (Z-order) curve through
//! their centroids and vertices numbered in order of first use. Patches of
//! the atlas follow face order, so neighbouring patches share cache lines
//! and pages, which the table-driven kernels depend on for speed.
//! `face_order[k]` is the input face that became face k.
BaseMesh spatially_ordered(const BaseMesh& mesh, std::vector<int>* face_order = nullptr);

//! The indices of `points` sorted along a Morton curve through their box:
//! queries asked in this order walk a spatial index through the cache.
std::vector<std::size_t> morton_order(const std::vector<Vec3>& points);

} // namespace meshpaint
