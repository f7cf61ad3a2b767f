// A geometry or colour-filter dab from start to end: where it edits (the
// painting level, or a coarser edit level: coarse_edit.h), the undo record,
// the weights, the move (sculpt.h) or the smoothing passes (smoothing.h),
// then the limit surface where the positions changed.
#pragma once

#include "atlas_types.h" // for BrushDab
#include "core/vec.h"
#include "paint/coarse_edit.h"
#include "paint/dab_context.h"
#include "paint/stroke.h"

#include <vector> // for std::vector

namespace meshpaint {

//! Smooths or moves geometry (or smooths colours) on `patches`; `towards`
//! is the limit normal at the dab (a grab: the path's step). `reweigh`
//! false keeps the weights of the previous call (a grab's later pulls).
void reshape_dab(const DabContext& context, CoarseEdits& coarse, const std::vector<int>& patches, const BrushDab& dab,
                 const Stroke& stroke, const Vec3& towards, bool reweigh = true);

//! After positions changed on `patches`: the limit surface and the patch
//! bounds there and on every patch sharing a corner with them
//! (Atlas::neighbourhood()). `list`, if given, holds the patches on the device.
void refresh_geometry(const DabContext& context, const std::vector<int>& patches, const cl::Buffer* list = nullptr);
//! The same given that neighbourhood.
void refresh_geometry(const DabContext& context, const PatchSet& around);

} // namespace meshpaint
