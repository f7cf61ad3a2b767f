// The smoothing family: smoothing passes under a dab (of the control points,
// or of the colours: blur), and the smear brush, which carries colour from
// dab to dab.
#pragma once

#include "atlas_types.h" // for BrushDab
#include "core/vec.h"
#include "paint/dab_context.h"
#include "paint/stroke.h"

#include <array>    // for std::array
#include <optional> // for std::optional
#include <vector>   // for std::vector

namespace meshpaint {

//! settings' Laplacian (or Taubin) passes on the welded mesh of `level`
//! over `patches`, weighted by `weights` (the dab's, at that level): the
//! control points, or with settings.target_colour the diffuse and specular
//! layers of the side painted. Edges and corners move only where every
//! patch sharing them is in the list.
void smooth_dab(const DabContext& context, const std::vector<int>& patches, const SmoothSettings& settings,
                int level, const cl::Buffer& weights);

//! One dab of the smear brush: lays down `carried` (paint_dab), then picks
//! up the weighted mean diffuse and specular colour under the dab into it.
void smear_dab(const DabContext& context, const std::vector<int>& patches, BrushDab dab,
               std::optional<std::array<Float4, 2>>& carried);

} // namespace meshpaint
