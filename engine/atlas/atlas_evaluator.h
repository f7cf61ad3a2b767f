// The kernels that refine, reduce and evaluate the atlas (subdivide.cl,
// limit.cl, reduce.cl) and make device patch sets (select.cl), run over
// AtlasTables on layers of any level: the atlas's evaluator, as OpenSubdiv's
// evaluators stream Far's tables.
#pragma once

#include "atlas/atlas_storage.h"
#include "atlas/atlas_tables.h"
#include "atlas/patch_set.h"
#include "cl/runtime.h"

#include <cstdint> // for std::uint8_t
#include <vector>  // for std::vector

namespace meshpaint {

//! A whole-tile kernel over some patches of a level, in the form the
//! evaluator picks (AtlasEvaluator::tile_launch()).
struct TileLaunch
{
  cl::Kernel& kernel;
  cl::NDRange global, local;
};

//! The per-texel form: `per_texel` over range_tiles() of `count` patches.
TileLaunch texel_launch(cl::Kernel& per_texel, const LevelLayout& layout, int count);

class AtlasEvaluator
{
public:
  //! Builds the kernels for `storage` and room for the side and corner
  //! kernels' results up to the level of `finest`.
  //! \throw DeviceError when the kernels do not build; cl::Error.
  AtlasEvaluator(Runtime& runtime, const AtlasTables& tables, AtlasStorage storage, const LevelLayout& finest);

  //! Whether whole-tile kernels run a work item per patch (CPU devices; see
  //! atlas_access.cl) or per texel; both give the same bits, and the setter
  //! is there to compare them.
  bool patch_items() const { return patch_items_; }
  //! patch_items() of a new evaluator on `device`.
  static bool patch_items_on(const DeviceInfo& device) { return !device.gpu; }
  void set_patch_items(bool on) { patch_items_ = on; }
  //! Whether subdivide() takes the corners of all its steps from one gather
  //! of the first level's rings (CPU devices: subdivide_corner_levels), or
  //! runs a corner kernel per step (GPUs, whose registers the rings would
  //! not fit). The same bits either way.
  bool corners_in_one_pass() const { return patch_items_; }
  //! Whether the step from `level` to the next runs no side kernel, its
  //! tile kernel walking each tile's own sides (CPU devices, the first two
  //! steps: subdivide_first_step, subdivide_second_step). The same bits.
  bool tiles_walk_sides(int level) const { return walks_sides(patch_items_, level); }
  //! tiles_walk_sides() of an evaluator with patch_items() `patch_items`,
  //! for plans made before there is one.
  static bool walks_sides(bool patch_items, int level) { return patch_items && level <= 2; }
  //! A whole-tile kernel over `count` patches of a level: the per-patch
  //! kernel over count items (count / patches_per_item, rounded up, for
  //! one that takes a patch per lane: lanes.cl), or the per-texel one over
  //! range_tiles(). The arguments are the same for both.
  TileLaunch tile_launch(cl::Kernel& per_texel, cl::Kernel& per_patch, const LevelLayout& layout, int count,
                         int patches_per_item = 1) const;

  //! Catmull-Clark steps on `set`: layers[k + 1] (level from + k + 1) from
  //! layers[k], the whole tiles of the set's patches, which needs every
  //! side and corner of them among its edges and rings (Reach::Any).
  //! With `last_tiles` false, the last step makes its corners but not its
  //! tiles (layers.back() is not written): the caller makes them from the
  //! corners, which start at the returned entry of corner_work().
  int subdivide(int from_level, const std::vector<cl::Memory>& layers, const PatchSet& set, bool last_tiles = true);
  //! Gaussian reduction steps from level `from` down to level `to`:
  //! levels[l - 2] (level l - 1) from levels[l - 1].
  void reduce(int from, int to, const std::vector<cl::Memory>& levels);
  //! Limit positions and normals of `level`'s control points `in` on the
  //! whole tiles of the set's patches (Reach::Any); with `bounds`, also
  //! each computed patch's bounding sphere (centre xyz, radius w; float4
  //! per patch).
  void limit(int level, const cl::Memory& in, const cl::Memory& positions, const cl::Memory& normals,
             const PatchSet& set, const cl::Buffer* bounds);
  //! Per cluster of PATCH_CLUSTER consecutive patches, a sphere around the
  //! spheres of `bounds` (cluster_bounds in limit.cl), into `clusters`:
  //! the clusters of the set's patches (host lists), or every cluster.
  void cluster_bounds(const cl::Buffer& bounds, const cl::Buffer& clusters, const PatchSet& set);
  //! The corner neighbourhood of `changed` (PatchSetMaker::neighbourhood())
  //! made on the device as flags; `list`, if given, holds `changed` there
  //! already. Leaves the flags of an earlier set stale.
  PatchSet flag_neighbourhood(const std::vector<int>& changed, const cl::Buffer* list);

  //! The side and corner kernels' results at the finest level (two float4
  //! per edge texel; per ring two, or one per subdivision step from level 1
  //! where that is more: corner_work_layers()), for whole-tile kernels of
  //! other families.
  const cl::Buffer& side_work() const { return side_work_; }
  const cl::Buffer& corner_work() const { return corner_work_; }

private:
  struct Arguments;
  //! The set as kernel arguments: lists uploaded where they are not yet.
  //! \throw std::logic_error for flags that a newer set overwrote.
  Arguments arguments(const PatchSet& set) const;

  Runtime& runtime_;
  const AtlasTables& tables_;
  AtlasStorage storage_;
  bool patch_items_;
  cl::Kernel subdivide_tiles_, subdivide_patches_, subdivide_edges_, subdivide_corners_, subdivide_corner_levels_;
  cl::Kernel subdivide_first_step_, subdivide_second_step_;
  cl::Kernel limit_tiles_, limit_patches_, limit_edges_, limit_corners_, patch_bounds_, cluster_bounds_;
  cl::Kernel reduce_interior_, reduce_edges_, reduce_edge_walks_, reduce_corners_, reduce_sectors_, reduce_patches_,
      reduce_second_step_;
  cl::Kernel flag_corners_, flag_ring_patches_, flag_borders_;
  cl::Buffer side_work_, corner_work_;
  int corner_layers_ = 2; // float4 per ring in corner_work_
  // A byte per ring: subdivide_corner_levels' rings whose later corners are
  // taken again from the levels.
  cl::Buffer ring_marks_;
  bool wide_rings_ = false; // any interior ring over subdivide_corner_levels' slots
  // Device sets: a byte per patch, edge and ring, and the generation of the
  // last set.
  cl::Buffer patch_flags_, edge_flags_, ring_flags_;
  std::uint8_t generation_ = 0;
};

} // namespace meshpaint
