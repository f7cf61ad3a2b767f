// Values per base vertex carried to the painting level by OpenSubdiv's
// primvar interpolation: how a mesh file's colours, other channel values
// and label ids reach a fresh painting surface.
#pragma once

#include "mesh/far_refiner.h"
#include "paint/paint_surface.h"
#include "reference/opensubdiv_reference.h"

#include <opensubdiv/far/primvarRefiner.h> // for Far::PrimvarRefiner

#include <vector> // for std::vector

namespace meshpaint {

//! `coarse` (one T per vertex of the surface's base mesh) refined level by
//! level to the painting level by Catmull-Clark's weights, then one T per
//! welded vertex there, in the order vertex_channel() uses. T is any
//! OpenSubdiv primvar: `Clear()` and `AddWithWeight(const T&, float)`.
template <typename T>
std::vector<T> refined_to_painting_level(PaintSurface& surface, std::vector<T> coarse)
{
  const BaseMesh& base = surface.atlas().base_mesh();
  const int level = surface.level();
  auto refiner = make_refiner(base);
  refine_uniform(*refiner, level, false);
  Far::PrimvarRefiner primvar(*refiner);
  for (int l = 1; l <= level; ++l) {
    std::vector<T> fine(std::size_t(refiner->GetLevel(l).GetNumVertices()));
    const T* src = coarse.data();
    T* dst = fine.data();
    primvar.Interpolate(l, src, dst);
    coarse = std::move(fine);
  }
  // Each welded vertex of the painting level, as OpenSubdiv numbers it.
  const std::vector<int> order = opensubdiv_vertex_order(base, surface.atlas().topology(), level);
  std::vector<T> out;
  out.reserve(order.size());
  for (const int v : order)
    out.push_back(coarse[std::size_t(v)]);
  return out;
}

} // namespace meshpaint
