// Weights and moves of the control points under a dab.

#include "paint/sculpt.h"

#include "paint/paint_device.h"

#include <utility> // for std::pair

namespace meshpaint {

namespace {

//! What the weights at `level` read besides the dab's own fields: the dab
//! with its parameter space counted in that level's texels, and at a
//! coarser edit level the patches' sides shared with others, which stay
//! put (their copies there would not move with them).
struct LevelDab
{
  int stride = 1;
  cl::Buffer outside; // null at the painting level
};

//! The limit positions and normals the weights at `level` stand on: the
//! painting level's, or a coarser edit level's in Multires.
std::pair<const cl::Memory&, const cl::Memory&> level_limit(const PaintState& s, int level)
{
  if (level < s.level)
    return {s.multires->base_positions(), s.multires->base_normals()};
  return {s.atlas.limit_positions_layer(), s.atlas.limit_normals_layer()};
}

LevelDab upload_dab(const DabContext& context, const std::vector<int>& patches, const BrushDab& dab, int level)
{
  const PaintState& s = context.state;
  Runtime& rt = s.atlas.runtime();
  LevelDab out;
  out.stride = s.layout().n / s.atlas.layout(level).n;
  if (level < s.level) {
    out.outside = device_copy(rt.context(), s.atlas.shared_outside(patches));
  }
  BrushDab at_level = dab; // parameter space counts texels of the level
  for (float& c : at_level.centre_texel)
    c /= float(out.stride);
  at_level.texel_size *= float(out.stride);
  s.device.dab = device_value(rt.context(), at_level);
  return out;
}

} // namespace

void weigh_dab(const DabContext& context, const std::vector<int>& patches, const cl::Buffer& list, const BrushDab& dab,
               int level)
{
  // At a coarser edit level, on the limit of that level's control points.
  // The patches come from the finest surface, so that level's weights may
  // reach the sides they share with other patches: those stay put.
  const PaintState& s = context.state;
  PaintDevice& d = s.device;
  const LevelLayout l = s.atlas.layout(level);
  const bool coarse = level < s.level;
  const LevelDab at = upload_dab(context, patches, dab, level);
  const auto limit = level_limit(s, level);
  const int count = int(patches.size());
  const Atlas::TileLaunch t = s.atlas.tile_launch(d.dab_weights, d.dab_weights_patches, l, count);
  launch(s.atlas.runtime().queue(), t.kernel, t.global, t.local, limit.first, limit.second, grid(l), list, count,
         d.dab, d.unfold, d.stamp, context.material(), cl_int(context.mask_painted), grid(s.layout()), at.stride,
         at.outside, coarse ? s.multires->base_weights() : d.weights);
}

void move_dab(const DabContext& context, const std::vector<int>& patches, const cl::Buffer& list, const BrushDab& dab,
              const Stroke& stroke, const Vec3& towards, int level, bool weigh_as_moved, const cl::Buffer& weights)
{
  const PaintState& s = context.state;
  PaintDevice& d = s.device;
  cl::CommandQueue& q = s.atlas.runtime().queue();
  const LevelLayout l = s.atlas.layout(level);
  const int count = int(patches.size());
  const int mode = stroke.tool == Tool::Inflate ? MOVE_INFLATE : stroke.tool == Tool::Flatten ? MOVE_FLATTEN
                                                                                               : MOVE_SCULPT;
  // A grab moves by the path's step times the weight.
  const float amount = stroke.tool == Tool::Grab ? 1.f : stroke.move().amount;
  const cl::Memory& pos = s.atlas.level_layer(level);
  const bool in_place = s.atlas.storage() == AtlasStorage::Buffer; // see geometry.cl
  const cl::Memory& moved = in_place ? pos : d.position_work;
  const auto [limit, normals] = level_limit(s, level);
  const cl_float4 centre{{dab.centre[0], dab.centre[1], dab.centre[2], 0.f}};
  const cl_float4 step{{towards[0], towards[1], towards[2], 0.f}};
  const auto tiles = range_tiles(l, count);
  if (weigh_as_moved) {
    const bool plain = dab.space == SPACE_OBJECT && dab.stamp_size[0] == 0 && !context.mask_painted;
    const LevelDab at = upload_dab(context, patches, dab, level);
    // A plain dab takes eight patches per work item where patches are items.
    const Atlas::TileLaunch t = plain ? s.atlas.tile_launch(d.move_dab, d.move_dab_lanes, l, count, PATCH_LANES)
                                      : s.atlas.tile_launch(d.move_dab, d.move_dab_patches, l, count);
    launch(q, t.kernel, t.global, t.local, pos, moved, limit, normals, grid(l), list, count, d.dab, d.unfold, d.stamp,
           context.material(), cl_int(context.mask_painted), grid(s.layout()), at.stride, at.outside, mode, amount,
           centre, step, cl_int(plain), dab.radius, cl_int(dab.falloff), dab.strength);
  } else {
    const Atlas::TileLaunch t = s.atlas.tile_launch(d.move_points, d.move_points_patches, l, count);
    launch(q, t.kernel, t.global, t.local, pos, moved, normals, grid(l), list, count, weights, mode, amount, centre,
           step);
  }
  if (!in_place)
    launch(q, d.positions.copy_tiles, tiles.first, tiles.second, d.position_work, pos, grid(l), list, count);
}

} // namespace meshpaint
