// The patch atlas on the device: one geometry image per level over the
// atlas's tables, refined, reduced and evaluated by its evaluator, and the
// limit surface of the finest level.
#pragma once

#include "atlas/atlas_evaluator.h"
#include "atlas/atlas_storage.h"
#include "atlas/atlas_tables.h"
#include "atlas/atlas_topology.h"
#include "atlas/memory_plan.h"
#include "atlas/patch_layout.h"
#include "atlas/patch_set.h"
#include "atlas/tile_ranges.h"
#include "cl/runtime.h"
#include "core/vec.h"
#include "mesh/base_mesh.h"

#include <cstdint> // for std::uint8_t
#include <memory>  // for std::shared_ptr, std::unique_ptr
#include <vector>  // for std::vector

namespace meshpaint {

class Atlas
{
public:
  //! Builds the first Catmull-Clark step of `mesh` (OpenSubdiv), the patch
  //! tables, and device storage for levels 1..max_level, with level 1 filled.
  //! The atlas works on `mesh` with its faces in spatial order (see
  //! spatially_ordered()); base_mesh() is that reordered mesh, whose face k
  //! is input face base_face_order()[k].
  //! \throw ResourceError when max_level does not fit the device, naming the
  //! largest level that does.
  Atlas(std::shared_ptr<Runtime> runtime, const BaseMesh& mesh, int max_level,
        AtlasStorage storage);
  ~Atlas();
  Atlas(const Atlas&) = delete;
  Atlas& operator=(const Atlas&) = delete;

  int max_level() const { return max_level_; }
  AtlasStorage storage() const { return storage_; }
  //! AtlasEvaluator::patch_items(): a work item per patch or per texel.
  bool patch_items() const { return evaluator_->patch_items(); }
  void set_patch_items(bool on) { evaluator_->set_patch_items(on); }
  using TileLaunch = meshpaint::TileLaunch;
  //! AtlasEvaluator::tile_launch(), for whole-tile kernels of other families.
  TileLaunch tile_launch(cl::Kernel& per_texel, cl::Kernel& per_patch, const LevelLayout& layout, int count,
                         int patches_per_item = 1) const
  {
    return evaluator_->tile_launch(per_texel, per_patch, layout, count, patches_per_item);
  }
  const AtlasTopology& topology() const { return tables_->topology(); }
  //! The tables on the device, for kernels of other families.
  const AtlasTables& tables() const { return *tables_; }
  AtlasEvaluator& evaluator() { return *evaluator_; }
  const AtlasEvaluator& evaluator() const { return *evaluator_; }
  const BaseMesh& base_mesh() const { return base_; }
  const std::vector<int>& base_face_order() const { return base_face_order_; }
  LevelLayout layout(int level) const;
  Runtime& runtime() { return *runtime_; }
  const std::shared_ptr<Runtime>& shared_runtime() const { return runtime_; }

  //! Catmull-Clark kernels: each level l+1 from level l, for from <= l < to.
  void subdivide(int from_level, int to_level);
  //! The same on a set only, at every level: the whole tiles of its patches,
  //! which needs every side and corner of them among its edges and rings
  //! (Reach::Any); the levels must be current around the set, and every
  //! patch holding a copy of what changed must be in it (the changed
  //! patches' neighbourhood()). With `last`, level to_level goes into that
  //! layer (of its layout) instead, and the atlas's own layer of that level
  //! stays as it is.
  void subdivide(int from_level, int to_level, const PatchSet& set, const cl::Memory* last = nullptr);
  //! The same up to the finest level, but for the last step's tiles: the
  //! level below the finest is made, and the finest level's corners, which
  //! start at the returned entry of evaluator().corner_work(); the caller
  //! makes the finest tiles (Multires decodes them as it makes them).
  int subdivide_but_last_tiles(int from_level, const PatchSet& set);
  //! Gaussian reduction kernels: each level l-1 from level l, to <= l-1 < from.
  void reduce(int from_level, int to_level);
  //! Limit positions and normals of the surface at max_level.
  void compute_limit();
  //! The same for the control points of another level, into the given
  //! layers of that level's layout (the atlas's own limit layers stay), on
  //! the whole tiles of the set's patches (Reach::Any). With `bounds`, also
  //! each computed patch's bounding sphere of its limit positions there
  //! (centre xyz, radius w; float4 per patch).
  void compute_limit_of(int level, const cl::Memory& positions, const cl::Memory& normals,
                        const PatchSet& set = PatchSet(), const cl::Buffer* bounds = nullptr);
  //! Waits for every queued kernel.
  void finish();

  //! The edges and rings that go with `patches` (sorted) by `reach`, as
  //! host lists.
  PatchSet patch_set(const std::vector<int>& patches, Reach reach) const;
  //! The set that subdivide() and update_limit() take after the positions
  //! of `changed` moved: those patches and every patch sharing a corner
  //! with one (each holds copies of moved texels' limit), by Reach::Any.
  //! `list`, if given, holds `changed` on the device already. From
  //! 1 / device_set_share() of the patches on, it is made on the device as
  //! flags instead of host lists; that leaves the flags of an earlier set
  //! stale (taking one then throws std::logic_error).
  PatchSet neighbourhood(const std::vector<int>& changed, const cl::Buffer* list = nullptr);
  static constexpr std::size_t kDeviceSetShare = 16;
  //! The two ways give the same sets; the setter is for tests that compare
  //! them (0: host lists always; the patch count: flags always).
  std::size_t device_set_share() const { return device_set_share_; }
  void set_device_set_share(std::size_t share) { device_set_share_ = share; }
  //! Whether a set made for `count` patches is made on the device as flags.
  bool sets_on_device(std::size_t count) const
  {
    return count * device_set_share_ >= std::size_t(topology().patch_count);
  }
  //! Per patch of `patches`, the sides (bits 0-3) and corners (bits 4-7) it
  //! shares with a patch not listed (as PatchSet::outside).
  std::vector<std::uint8_t> shared_outside(const std::vector<int>& patches) const;
  //! `patches` and every patch sharing a corner with one, in patch order,
  //! each once.
  std::vector<int> corner_neighbourhood(const std::vector<int>& patches) const;
  //! Recomputes the limit layers on a set only (after editing positions
  //! there): the whole tiles of the set's patches, as compute_limit_of().
  //! Every patch holding a copy of a moved texel's limit must be in the set:
  //! the edited patches' neighbourhood().
  void update_limit(const PatchSet& set);
  //! After the finest level was rewritten to what it was except on a set
  //! whose limit the caller recomputes with update_limit(): lets that update
  //! stay on the set instead of covering everything.
  void assume_limit_current();
  //! Device layers for kernels of other families (brush.cl, geometry.cl),
  //! which address them with the same storage macros.
  const cl::Memory& level_layer(int level);
  const cl::Memory& limit_normals_layer();

  //! Positions of every texel of `level`, patch-major (LevelLayout::index).
  std::vector<Float4> read_positions(int level);
  void write_positions(int level, const std::vector<Float4>& texels);
  //! The limit layers, recomputed first if the finest level changed since.
  //! The device layer is for kernels of other families (brush.cl), which
  //! address it with the same storage macros.
  const cl::Memory& limit_positions_layer();
  //! Per patch, the bounding sphere of its limit positions (centre xyz,
  //! radius w), kept with the limit layers.
  const cl::Buffer& limit_bounds();
  //! Per cluster of PATCH_CLUSTER consecutive patches, a bounding sphere of
  //! their limit_bounds() (cluster_count() of them), kept with those.
  const cl::Buffer& limit_cluster_bounds();
  std::vector<Float4> read_limit_positions();
  std::vector<Float4> read_limit_normals();

private:
  std::shared_ptr<Runtime> runtime_;
  AtlasStorage storage_;
  std::size_t device_set_share_ = kDeviceSetShare;
  int max_level_;
  BaseMesh base_;
  std::vector<int> base_face_order_;
  std::unique_ptr<AtlasTables> tables_;
  std::unique_ptr<AtlasEvaluator> evaluator_;
  // Its scratch makes patch_set(), shared_outside() and corner_neighbourhood() const in name only: calls on one
  // atlas must not overlap.
  std::unique_ptr<PatchSetMaker> sets_;
  std::vector<cl::Memory> levels_;      // index l - 1
  cl::Memory limit_positions_, limit_normals_; // null until first computed
  cl::Buffer limit_bounds_;
  cl::Buffer limit_clusters_; // cluster_bounds() of limit_bounds_, kept with it
  bool limit_current_ = false; // limit layers match the finest level
};

} // namespace meshpaint
