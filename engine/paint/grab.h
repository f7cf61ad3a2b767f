// The grab tool: the region under a stroke's first dab, taken once, then
// pulled along the path by each later dab's step, with the weights it had
// when taken.
#pragma once

#include "atlas_types.h" // for BrushDab
#include "core/vec.h"
#include "paint/coarse_edit.h"
#include "paint/dab_context.h"
#include "paint/stroke.h"
#include "paint/stroke_report.h"

#include <cstddef> // for std::size_t
#include <vector>  // for std::vector

namespace meshpaint {

class GrabRegion
{
public:
  //! Sample `index` of the stroke's `samples`. The first takes the region
  //! under it (when `mine`: in a scene it may be another object's), with
  //! the dab's radius and strength from its pressure, placed by `place`;
  //! false when it misses the surface (the stroke ends there). A later one
  //! pulls a held region to its centre.
  bool step(const DabContext& context, CoarseEdits& coarse, const Stroke& stroke, BrushDab& dab,
            const std::vector<DabSample>& samples, std::size_t index, bool mine, const PlaceDab& place,
            StrokeReport& report);
  //! The last pull, to the end of the stroke's whole path, which the dabs'
  //! spacing may fall short of; the report's dab count.
  void end(const DabContext& context, CoarseEdits& coarse, const Stroke& stroke, const BrushDab& dab,
           StrokeReport& report);

private:
  void pull(const DabContext& context, CoarseEdits& coarse, const Stroke& stroke, const BrushDab& dab, const Vec3& to,
            StrokeReport& report);

  bool held_ = false;
  std::vector<int> patches_;
  Vec3 at_{0.f, 0.f, 0.f}; // where the last pull ended
  std::size_t moves_ = 0;
};

} // namespace meshpaint
