// Label edits that are no brush: fill (the connected region of one class
// around a point) and merge (one class into another), over a painting
// surface's state. Each decides on the host from the label layer as read and
// returns the edit; the surface remembers the tiles for undo, then
// write_labels() writes them.
#pragma once

#include "atlas_types.h" // for CullRecord
#include "paint/paint_state.h"
#include "paint/stroke.h"

#include "core/vec.h"

#include <cstddef> // for std::size_t
#include <vector>  // for std::vector

namespace meshpaint {

//! Class `id` into the label channel at `texels`: patch-major indices into
//! `material`, the whole material layer as read.
struct LabelEdit
{
  std::vector<Float4> material;
  std::vector<std::size_t> texels;
  std::vector<int> patches; //!< the tiles of `texels`, ascending: what the edit changes
  int id = 0;
};

//! Fill: the texels connected to `seed` (the texel closest to the brush's
//! point) through texels of its class, across patch sides and corners
//! (welded vertices), become class settings.value[CHANNEL_LABEL]: neighbours
//! along the texel grid's sides, and with settings.fill_diagonals across its
//! corners too. No texels where that class is locked or not the only-over
//! class.
LabelEdit fill_labels(const PaintState& state, const CullRecord& seed, const PaintSettings& settings);
//! Merge: every texel of class settings.only_over_label becomes class
//! settings.value[CHANNEL_LABEL], the mask notwithstanding; no texels where
//! that class is locked.
LabelEdit merge_labels(const PaintState& state, const PaintSettings& settings);
//! The edit's class into its texels, on the host and on the device.
void write_labels(const PaintState& state, LabelEdit& edit);

} // namespace meshpaint
