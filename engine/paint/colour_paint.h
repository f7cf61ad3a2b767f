// Colour paint: the paint equation under a dab (paint, label, wash, dip),
// spray droplets, and the stroke's pattern samples, brush image and label
// guards on the device for the kernels.
#pragma once

#include "atlas_types.h" // for BrushDab
#include "paint/dab_context.h"
#include "paint/paint_state.h"
#include "paint/stroke.h"

#include <cstdint> // for std::uint64_t
#include <vector>  // for std::vector

namespace meshpaint {

//! The dab's paint on `patches` (remembered first), on the side it paints;
//! labels and displacement, which belong to the surface, on the outside.
void paint_dab(const DabContext& context, const std::vector<int>& patches, const BrushDab& dab);

//! One dab of spray paint: droplets at random points of the brush's disc on
//! the screen (seeded by the stroke's seed and the dab's `index`), each a
//! small object-space dab painted where it lands (placed by `place`).
void spray_dab(const DabContext& context, const std::vector<int>& patches, const BrushDab& dab,
               const Stroke& stroke, std::uint64_t index, const PlaceDab& place);

//! The stroke's pattern samples, brush image (as grey) and locked label
//! classes to the device; their sizes and the only-over class into `dab`.
//! \throw InputError when a raster's samples do not match its size.
void upload_rasters(const PaintState& state, const Stroke& stroke, BrushDab& dab);

} // namespace meshpaint
