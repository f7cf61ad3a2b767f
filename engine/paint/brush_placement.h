// Brush placement on a painting surface: where a dab lands (the closest
// limit texel within its radius), the patches it may change (those connected
// to the centre through sides within its reach, never through the air), and
// a parameter dab's patches laid flat.
#pragma once

#include "atlas_types.h" // for BrushDab, CullRecord
#include "core/vec.h"
#include "paint/paint_state.h"

#include <array>   // for std::array
#include <cstdint> // for std::uint8_t
#include <vector>  // for std::vector

namespace meshpaint {

//! A texel of the atlas at the painting level (CullRecord's patch and
//! closest_texel, row-major in the tile); none while patch < 0.
struct SnapHint
{
  int patch = -1;
  int texel = -1;
};

//! The flood over patches that finds a dab's reach, with its scratch kept
//! from dab to dab.
class BrushPlacement
{
public:
  BrushPlacement() = default;
  //! For the patches of `topology`.
  explicit BrushPlacement(const AtlasTopology& topology);

  //! The patches one dab at `point` would touch: those connected to the
  //! closest surface point along the surface within `radius`, sorted. Empty
  //! when no surface is within the radius. `centre` receives the snapped
  //! centre, `centre_normal` the limit normal there.
  //! `reach` (default: the radius) bounds the search for connected patches
  //! when the brush's footprint reaches further than its radius in space
  //! (tangent and screen brushes); `closest` receives the centre's texel.
  std::vector<int> brush_patches(const PaintState& state, const Vec3& point, float radius, Vec3* centre = nullptr,
                                 Vec3* centre_normal = nullptr, float reach = 0.f, CullRecord* closest = nullptr);
  //! Distance from `point` to the closest surface point within `radius`;
  //! infinity when there is none.
  float distance_to(const PaintState& state, const Vec3& point, float radius);
  //! Where the next dab is expected to snap: patch `patch` at (u, v) in
  //! [0, 1]^2. Only the search gets cheaper: any texel gives every dab the
  //! same centre and patches. Out of range (a patch < 0): no hint. Each dab
  //! leaves its own texel as the hint for the next.
  void hint_snap(const PaintState& state, int patch, double u, double v);

private:
  SnapHint hint_;
  std::vector<std::array<int, 4>> neighbours_; // per patch side: the patch across, -1 on a border
  //! Per patch: bit s set if side s comes within the dab's reach, or
  //! REACH_NONE; then the flood's mark. One more entry, REACH_NONE, where
  //! closed sides lead.
  std::vector<std::uint8_t> open_sides_;
  std::vector<int> queue_; // the flood's queue: room for every patch, and the sentinel

};

//! A parameter dab's patches around `centre_patch`, laid flat in its texels
//! (unfold()); their maps to the device, in the order returned.
std::vector<int> unfold_dab(const PaintState& state, int centre_patch, BrushDab& dab);

} // namespace meshpaint
