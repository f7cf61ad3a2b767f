// The sculpt family: a dab's weights on the control points, and the moves
// of sculpt, inflate, flatten and grab's pull by them.
#pragma once

#include "atlas_types.h" // for BrushDab
#include "core/vec.h"
#include "paint/dab_context.h"
#include "paint/stroke.h"

#include <vector> // for std::vector

namespace meshpaint {

//! The dab's weights on the texels of `patches` (`list`: them on the
//! device) at `level`, into that level's weight buffer (the painting
//! level's, or a coarser edit level's in Multires, on the limit of that
//! level's control points, where the sides the patches share with others
//! stay put).
void weigh_dab(const DabContext& context, const std::vector<int>& patches, const cl::Buffer& list, const BrushDab& dab,
               int level);

//! Moves the control points of `level` on `patches` (`list`) for the
//! stroke's tool: sculpt and inflate along the normal, flatten towards the
//! plane at the centre, grab by `towards` (the path's step). With
//! `weigh_as_moved` (not grab) the kernel weighs as it moves, to the bits
//! weigh_dab() would give; else it moves by `weights` (weigh_dab()'s).
void move_dab(const DabContext& context, const std::vector<int>& patches, const cl::Buffer& list, const BrushDab& dab,
              const Stroke& stroke, const Vec3& towards, int level, bool weigh_as_moved, const cl::Buffer& weights);

} // namespace meshpaint
