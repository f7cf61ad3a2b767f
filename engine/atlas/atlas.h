// The patch atlas on the device: one geometry image per level, the
// connectivity tables, and the kernels that refine, reduce and evaluate it.
#pragma once

#include "atlas/atlas_topology.h"
#include "atlas/patch_layout.h"
#include "cl/runtime.h"
#include "core/marks.h"
#include "core/vec.h"
#include "mesh/base_mesh.h"

#include <array>   // for std::array
#include <cstdint> // for std::uint8_t
#include <memory>  // for std::shared_ptr, std::unique_ptr
#include <utility> // for std::pair
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

//! How atlas layers are stored on the device. Same kernels, two access paths.
enum class AtlasStorage
{
  Buffer, //!< linear float4 buffers, 2D indexing: the fast path on CPUs
  Image   //!< image2d_t RGBA float: for devices with texture units
};

//! Default for a device: images on GPUs that support them, buffers otherwise.
//! MESHPAINT_STORAGE=buffer|image overrides it.
AtlasStorage default_storage(const DeviceInfo& device);
//! \throw InputError for anything but "buffer" or "image".
AtlasStorage parse_storage(const std::string& name);
const char* storage_name(AtlasStorage storage);
//! Build options of kernels that address atlas layers in `storage` on
//! `device` (CPUs prefetch tiles that gathering kernels read out of order).
std::string storage_options(AtlasStorage storage, const DeviceInfo& device);

//! A zero-filled float4 layer of a level in the given storage: scratch and
//! saved copies of levels, which the atlas's kernels address alike.
cl::Memory allocate_layer(Runtime& runtime, const LevelLayout& layout, AtlasStorage storage);

//! Device memory an atlas up to `level` needs, checked before allocating.
struct MemoryPlan
{
  LevelLayout finest;
  std::size_t largest_allocation = 0; //!< bytes, one layer of the finest level
  std::size_t total = 0;              //!< bytes, all levels plus limit layers
};
MemoryPlan plan_memory(const AtlasTopology& topology, int level, AtlasStorage storage);
//! The (tile, tiles_x) pair kernels take to address a level.
inline cl_int2 grid(const LevelLayout& l) { return cl_int2{{l.tile, l.tiles_x}}; }

//! Global and local range for `count` whole tiles of a level, a work item per
//! texel: (tile, tile * count).
std::pair<cl::NDRange, cl::NDRange> range_tiles(const LevelLayout& layout, int count);
//! The same for the texels strictly inside the tiles (interior_texel() in
//! atlas_access.cl): (n - 1, (n - 1) * count). Levels from 2 on.
std::pair<cl::NDRange, cl::NDRange> range_interiors(const LevelLayout& layout, int count);

//! Bytes of one float4 layer of a level in the given storage.
std::size_t layer_bytes(const LevelLayout& layout, AtlasStorage storage);

//! Why an atlas up to `level` does not fit the device (image size, largest
//! allocation, total memory, 32-bit texel indices), or "" when it fits.
std::string fit_problem(const AtlasTopology& topology, int level, const DeviceInfo& device,
                        AtlasStorage storage);
//! Highest level that fits, 0 when none does.
int largest_fitting_level(const AtlasTopology& topology, const DeviceInfo& device, AtlasStorage storage);

//! The patch tables of a mesh without a device: one Catmull-Clark step
//! through OpenSubdiv.
AtlasTopology atlas_topology_of(const BaseMesh& mesh);

//! Some patches, with the patch edges and corner rings that go with them,
//! as lists for the kernels that take a subset.
struct PatchSet
{
  std::vector<int> patches; //!< sorted
  std::vector<int> edges;   //!< indices into AtlasTopology::edges
  std::vector<int> rings;   //!< indices into the device's ring table
  std::vector<int> corners; //!< the level-1 vertex of each ring
  //! Reach::All only: per patch, the sides (bits 0-3) and corners (bits
  //! 4-7) it shares with a patch outside the set (texel_border()'s bits).
  std::vector<std::uint8_t> outside;
};

//! Whether an edge or ring goes with a set of patches when any of its
//! patches is in the set, or only when all are.
enum class Reach
{
  Any,
  All
};

//! A set of patches with every side and corner of them, as the kernels
//! that take a subset take it: device lists and their lengths; or null
//! lists and the full counts, and then either flags made on the device
//! (select.cl: the items whose flag holds `generation`; valid until the
//! atlas makes its next flags) or nothing (every item).
struct DeviceSet
{
  cl::Buffer patches, edges, rings;
  int patch_count = 0, edge_count = 0, ring_count = 0;
  cl::Buffer patch_flags, edge_flags, ring_flags;
  int generation = 0;
};

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
  //! Whether whole-tile kernels run a work item per patch (CPU devices; see
  //! atlas_access.cl) or per texel; both give the same bits, and the setter
  //! is there to compare them.
  bool patch_items() const { return patch_items_; }
  void set_patch_items(bool on) { patch_items_ = on; }
  //! A whole-tile kernel over `count` patches of a level in that form: the
  //! per-patch kernel over count items, or the per-texel one over
  //! range_tiles(). The arguments are the same for both.
  struct TileLaunch
  {
    cl::Kernel& kernel;
    cl::NDRange global, local;
  };
  TileLaunch tile_launch(cl::Kernel& per_texel, cl::Kernel& per_patch, const LevelLayout& layout, int count) const;
  const AtlasTopology& topology() const { return topology_; }
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
  //! patches' corner neighbourhood). With
  //! `last`, level to_level goes into that layer (of its layout) instead,
  //! and the atlas's own layer of that level stays as it is.
  void subdivide(int from_level, int to_level, const PatchSet* set, const cl::Memory* last = nullptr);
  //! The same with the set as the device takes it (neighbourhood_on_device()).
  void subdivide(int from_level, int to_level, const DeviceSet& set, const cl::Memory* last = nullptr);
  //! Gaussian reduction kernels: each level l-1 from level l, to <= l-1 < from.
  void reduce(int from_level, int to_level);
  //! Limit positions and normals of the surface at max_level.
  void compute_limit();
  //! The same for the control points of another level, into the given
  //! layers of that level's layout (the atlas's own limit layers stay);
  //! with a set, the whole tiles of its patches only, which needs every
  //! side and corner of them among its edges and rings (Reach::Any).
  //! With `bounds`, also each computed patch's bounding sphere of its limit
  //! positions there (centre xyz, radius w; float4 per patch).
  void compute_limit_of(int level, const cl::Memory& positions, const cl::Memory& normals,
                        const PatchSet* set = nullptr, const cl::Buffer* bounds = nullptr);
  //! Waits for every queued kernel.
  void finish();

  //! The edges and rings that go with `patches` (sorted) by `reach`.
  PatchSet patch_set(const std::vector<int>& patches, Reach reach) const;
  //! The set that subdivide() and update_limit() take after the positions
  //! of `changed` moved: those patches and every patch sharing a corner
  //! with one (each holds copies of moved texels' limit), by Reach::Any.
  PatchSet neighbourhood_set(const std::vector<int>& changed) const;
  //! Per patch of `patches`, the sides (bits 0-3) and corners (bits 4-7) it
  //! shares with a patch not listed (as PatchSet::outside).
  std::vector<std::uint8_t> shared_outside(const std::vector<int>& patches) const;
  //! Recomputes the limit layers on a set only (after editing positions
  //! there): the whole tiles of the set's patches, as compute_limit_of().
  //! Every patch holding a copy of a moved texel's limit must be in the set:
  //! the edited patches' corner neighbourhood.
  void update_limit(const PatchSet& set);
  void update_limit(const DeviceSet& set);
  //! A PatchSet's lists on the device; null: every patch, edge and ring.
  DeviceSet device_set(const PatchSet* set) const;
  //! neighbourhood_set(changed) in the form the device takes; `list`, if
  //! given, holds `changed` there already. From 1 / device_set_share() of
  //! the patches on, the set is worked out on the device as flags instead
  //! of host lists; that leaves the flags of an earlier set stale (taking
  //! one then throws std::logic_error).
  DeviceSet neighbourhood_on_device(const std::vector<int>& changed, const cl::Buffer* list = nullptr);
  static constexpr std::size_t kDeviceSetShare = 16;
  //! The two ways give the same sets; the setter is for tests that compare
  //! them (0: host lists always; the patch count: flags always).
  std::size_t device_set_share() const { return device_set_share_; }
  void set_device_set_share(std::size_t share) { device_set_share_ = share; }
  //! After the finest level was rewritten to what it was except on a set
  //! whose limit the caller recomputes with update_limit(): lets that update
  //! stay on the set instead of covering everything.
  void assume_limit_current();
  //! Device layers for kernels of other families (brush.cl, geometry.cl),
  //! which address them with the same storage macros.
  const cl::Memory& level_layer(int level);
  const cl::Memory& limit_normals_layer();
  const cl::Buffer& edge_table() const;
  //! For whole-tile kernels of other families (border_entry() in
  //! atlas_access.cl): the per-patch side and ring tables, and room for
  //! the side and corner kernels' results at the finest level (two float4
  //! per entry), which the atlas's own kernels also use between launches.
  struct BorderWork
  {
    const cl::Buffer &patch_sides, &patch_rings, &sides, &corners;
  };
  BorderWork border_work() const;
  const cl::Buffer& ring_table() const;
  const cl::Buffer& slot_table() const;

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
  std::vector<Float4> read_limit_positions();
  std::vector<Float4> read_limit_normals();

private:
  struct Layer;
  struct Kernels;
  std::vector<Float4> read_layer(const Layer& layer, const LevelLayout& l);
  void write_layer(Layer& layer, const LevelLayout& l, const std::vector<Float4>& texels);
  Layer make_layer(const LevelLayout& l);
  //! compute_limit_of() on a set as device lists or flags.
  void limit_on(int level, const cl::Memory& positions, const cl::Memory& normals, const DeviceSet& set,
                const cl::Buffer* bounds);
  //! Throws where `set` has flags that a newer set overwrote.
  void check_current(const DeviceSet& set) const;
  //! The set of `patches` (in patch order, and the ones patch_marks_ holds).
  PatchSet marked_set(std::vector<int> patches, Reach reach) const;
  //! PatchSet::outside of patch p, the set being what patch_marks_ holds
  //! (after begin_outside()).
  std::uint8_t outside_bits(int p) const;
  //! Whether a patch at corner v lies outside that set (kept per ring).
  bool ring_outside(int v) const;
  void begin_outside() const;

  std::shared_ptr<Runtime> runtime_;
  AtlasStorage storage_;
  bool patch_items_ = false;
  std::size_t device_set_share_ = kDeviceSetShare;
  int max_level_;
  BaseMesh base_;
  std::vector<int> base_face_order_;
  AtlasTopology topology_;
  std::vector<Layer> levels_;  // index l - 1
  std::unique_ptr<Layer> limit_positions_, limit_normals_;
  cl::Buffer limit_bounds_;
  bool limit_current_ = false; // limit layers match the finest level
  std::unique_ptr<Kernels> kernels_;
  std::vector<int> device_ring_; // level-1 vertex -> index in the device's ring table
  // Scratch of patch_set(), neighbourhood_set() and shared_outside(), which
  // a brush step calls on most of the atlas: kept, so that a call costs only
  // what it visits (and two calls on one atlas must not overlap).
  mutable Marks patch_marks_, edge_marks_, ring_marks_, ring_seen_, ring_known_;
  mutable std::vector<std::uint8_t> ring_outside_; // ring_outside(), where ring_known_
};

} // namespace meshpaint
