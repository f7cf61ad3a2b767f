// Per-label measures of a painted surface: area, centroid, bounds.
#pragma once

#include "paint/paint_surface.h"

#include <vector> // for std::vector

namespace meshpaint {

//! One label class as painted on the surface.
struct LabelStats
{
  int id = 0;
  std::size_t vertices = 0; //!< welded vertices carrying the label
  double area = 0;          //!< world units squared
  Vec3 centroid{};          //!< area-weighted
  Vec3 bbox_min{}, bbox_max{};
};

//! Every label present on the surface, by increasing id. Each quad's area
//! (two triangles) is shared equally by its four corners, and each corner
//! gives its share to its vertex's label; the centroid weighs vertices by
//! those shares, the bounds hold the label's vertices.
std::vector<LabelStats> label_stats(const PaintedSurface& surface);

//! Total area of the surface's quads.
double surface_area(const WeldedSurface& surface);

} // namespace meshpaint
