#include "atlas/multires.h"

#include "cl/launch.h"
#include "cl/kernel_programs.h"
#include "atlas/memory_plan.h"
#include "atlas_types.h" // for PATCH_LANES
#include "core/errors.h"

#include <algorithm> // for std::max
#include <cstdint>   // for std::uint8_t
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

constexpr std::size_t kGroup = 64;

} // namespace

struct Multires::Device
{
  cl::Program program;
  cl::Kernel encode_details, encode_patches, decode_tiles, decode_patches, decode_edges, decode_corners, patch_extent;
  cl::Kernel subdivide_decode_first, subdivide_decode_second, subdivide_encode_first, subdivide_encode_second;
  cl::Memory smooth;    // U = up(base) at the finest level, unless tiles_as_made()
  cl::Buffer details;   // per finest texel: (t, b, n) coordinates of S - U
  cl::Buffer weights;   // edit-level weights
  cl::Memory positions, normals; // edit-level limit (layers of the level below the finest, used in part)
  cl::Buffer extent;    // per patch
  cl::Buffer owned;     // per patch: the parts whose details it holds (encode_details)
};

namespace {

//! Per patch, the texel_border() bits of the sides and corners whose
//! details decoding reads there: a side in its edge's first patch, a
//! corner in its ring's first slot's patch.
std::vector<std::uint8_t> owned_parts(const AtlasTopology& topo)
{
  std::vector<std::uint8_t> owned(std::size_t(topo.patch_count), 0);
  for (const PatchEdge& e : topo.edges)
    owned[std::size_t(e.patch[0])] |= std::uint8_t(1 << e.side[0]);
  for (const CornerRing& r : topo.rings) {
    const CornerSlot& first = topo.slots[std::size_t(r.first)];
    owned[std::size_t(first.patch)] |= std::uint8_t(16 << first.corner);
  }
  return owned;
}

//! Whether the finest level's tiles are encoded and decoded as the last
//! step of subdivision makes them (CPUs, a finest level 2 or 3), so that U
//! at the finest level never goes through memory and has no layer.
bool tiles_as_made(int finest, bool patch_items)
{
  return (finest == 2 || finest == 3) && AtlasEvaluator::walks_sides(patch_items, finest - 1);
}
bool tiles_as_made(const Atlas& atlas) { return tiles_as_made(atlas.max_level(), atlas.evaluator().patch_items()); }

//! The layout of the edit level's limit and weights: every level's tiles
//! sit in the same rows of tiles (tiles_x), so the level below the finest
//! holds any edit level's.
LevelLayout edit_layout(int patches, int finest) { return level_layout(patches, std::max(1, finest - 1)); }
LevelLayout edit_layout(const Atlas& atlas) { return edit_layout(atlas.topology().patch_count, atlas.max_level()); }

} // namespace

std::size_t Multires::device_bytes(int patches, int finest, AtlasStorage storage, bool patch_items)
{
  const LevelLayout f = level_layout(patches, finest), edit = edit_layout(patches, finest);
  return (tiles_as_made(finest, patch_items) ? 0 : layer_bytes(f, storage)) + 2 * layer_bytes(edit, storage) +
         f.texels() * sizeof(cl_float4) + edit.texels() * sizeof(float) +
         std::size_t(std::max(f.patches, 1)) * (sizeof(float) + 1);
}

std::size_t Multires::device_bytes(const Atlas& atlas)
{
  return device_bytes(atlas.topology().patch_count, atlas.max_level(), atlas.storage(),
                      atlas.evaluator().patch_items());
}

Multires::Multires(Atlas& atlas) : atlas_(atlas), device_(std::make_unique<Device>())
{
  Runtime& rt = atlas_.runtime();
  const LevelLayout f = atlas_.layout(atlas_.max_level());
  Device& d = *device_;
  try {
    d.program = kernel_program(rt, KernelProgram::Detail, storage_options(atlas_.storage(), rt.info()));
    d.encode_details = cl::Kernel(d.program, "encode_details");
    d.encode_patches = cl::Kernel(d.program, "encode_patches");
    d.decode_tiles = cl::Kernel(d.program, "decode_tiles");
    d.decode_patches = cl::Kernel(d.program, "decode_patches");
    d.decode_edges = cl::Kernel(d.program, "decode_edges");
    d.decode_corners = cl::Kernel(d.program, "decode_corners");
    d.patch_extent = cl::Kernel(d.program, "patch_extent");
    d.subdivide_decode_first = cl::Kernel(d.program, "subdivide_decode_first");
    d.subdivide_decode_second = cl::Kernel(d.program, "subdivide_decode_second");
    d.subdivide_encode_first = cl::Kernel(d.program, "subdivide_encode_first");
    d.subdivide_encode_second = cl::Kernel(d.program, "subdivide_encode_second");
    if (!tiles_as_made(atlas_))
      d.smooth = allocate_layer(rt, f, atlas_.storage());
    const LevelLayout edit = edit_layout(atlas_);
    d.positions = allocate_layer(rt, edit, atlas_.storage());
    d.normals = allocate_layer(rt, edit, atlas_.storage());
    d.details = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, f.texels() * sizeof(cl_float4));
    // Encoding leaves the copies that decoding never reads: they hold 0.
    rt.queue().enqueueFillBuffer(d.details, cl_float4{}, 0, f.texels() * sizeof(cl_float4));
    d.owned = device_copy(rt.context(), owned_parts(atlas_.topology()));
    d.weights = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, edit.texels() * sizeof(float));
    d.extent = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, std::max(f.patches, 1) * sizeof(float));
  } catch (const cl::Error& e) {
    throw DeviceError("cannot set up multiresolution editing on " + rt.info().name + ": " + describe(e));
  }
}

Multires::~Multires() = default;

std::size_t Multires::allocated_bytes() const
{
  const Device& d = *device_;
  std::size_t total = 0;
  for (const cl::Memory* m : {&d.smooth, &d.positions, &d.normals, static_cast<const cl::Memory*>(&d.details),
                              static_cast<const cl::Memory*>(&d.owned), static_cast<const cl::Memory*>(&d.weights),
                              static_cast<const cl::Memory*>(&d.extent)})
    if ((*m)())
      total += m->getInfo<CL_MEM_SIZE>();
  return total;
}

std::size_t Multires::Memo::bytes() const
{
  std::size_t b = details.size() * sizeof(Float4) + extent.size() * sizeof(float);
  for (const auto& level : levels)
    b += level.size() * sizeof(Float4);
  return b;
}

void Multires::invalidate()
{
  level_ = encoded_level_ = -1;
  ++generation_;
}

bool Multires::resume(const State& state)
{
  const bool in_place = state.generation == generation_ && (state.level < 0 || state.level == encoded_level_);
  level_ = in_place ? state.level : -1;
  return in_place;
}

Multires::Memo Multires::save()
{
  Memo m;
  m.state = {encoded_level_, generation_};
  if (encoded_level_ < 0)
    return m;
  m.details = read_details();
  m.extent = extent_;
  for (int l = encoded_level_; l < atlas_.max_level(); ++l)
    m.levels.push_back(atlas_.read_positions(l));
  return m;
}

void Multires::load(const Memo& m)
{
  level_ = -1;
  encoded_level_ = m.state.level;
  generation_ = m.state.generation;
  if (m.state.level < 0)
    return;
  atlas_.runtime().queue().enqueueWriteBuffer(device_->details, CL_TRUE, 0, m.details.size() * sizeof(Float4),
                                              m.details.data());
  extent_ = m.extent;
  for (std::size_t k = 0; k < m.levels.size(); ++k)
    atlas_.write_positions(m.state.level + int(k), m.levels[k]);
}

std::vector<Float4> Multires::read_details()
{
  std::vector<Float4> out(atlas_.layout(atlas_.max_level()).texels());
  atlas_.runtime().queue().enqueueReadBuffer(device_->details, CL_TRUE, 0, out.size() * sizeof(Float4), out.data());
  return out;
}

const cl::Buffer& Multires::base_weights() const { return device_->weights; }
const cl::Memory& Multires::base_positions() const { return device_->positions; }
const cl::Memory& Multires::base_normals() const { return device_->normals; }

void Multires::encode(int level)
{
  const int finest = atlas_.max_level();
  if (level < 1 || level >= finest)
    throw InputError("cannot edit at level " + std::to_string(level) + ": the surface's levels below its finest are 1.." +
                     std::to_string(finest - 1));
  Device& d = *device_;
  cl::CommandQueue& q = atlas_.runtime().queue();
  const LevelLayout f = atlas_.layout(finest);
  const cl::Memory& fine = atlas_.level_layer(finest);
  try {
    // The finest level keeps S, and so does its limit: the details are
    // taken from U as the last step makes it (tiles_as_made()), else from U
    // in a layer of its own.
    atlas_.reduce(finest, level);
    if (tiles_as_made(atlas_)) {
      const int corner_base = atlas_.subdivide_but_last_tiles(level, PatchSet());
      const AtlasTables& tables = atlas_.tables();
      launch(q, finest == 2 ? d.subdivide_encode_first : d.subdivide_encode_second,
             cl::NDRange(round_up(f.patches, kGroup)), cl::NDRange(kGroup), atlas_.level_layer(finest - 1),
             grid(atlas_.layout(finest - 1)), grid(f), cl_int(f.patches), tables.patch_rings(), tables.patch_across(),
             atlas_.evaluator().corner_work(), cl_int(corner_base), fine, d.owned, d.details, d.extent);
    } else {
      atlas_.subdivide(level, finest, PatchSet(), &d.smooth);
      const Atlas::TileLaunch t = atlas_.tile_launch(d.encode_details, d.encode_patches, f, f.patches, PATCH_LANES);
      // The per-patch kernel measures each tile's extent as it goes.
      const bool measures = &t.kernel == &d.encode_patches;
      if (measures)
        d.encode_patches.setArg(6, d.extent); // its last, beyond encode_details' own
      launch(q, t.kernel, t.global, t.local, fine, d.smooth, grid(f), f.patches, d.owned, d.details);
      if (!measures)
        launch(q, d.patch_extent, cl::NDRange(round_up(f.patches, kGroup)), cl::NDRange(kGroup), fine, grid(f),
               cl::Buffer(), f.patches, d.extent);
    }
    extent_.resize(std::size_t(f.patches));
    q.enqueueReadBuffer(d.extent, CL_TRUE, 0, extent_.size() * sizeof(float), extent_.data());
  } catch (const cl::Error& e) {
    invalidate();
    throw DeviceError("encoding details failed on " + atlas_.runtime().info().name + ": " + describe(e));
  }
  level_ = encoded_level_ = level;
  ++generation_;
}

std::vector<int> Multires::reach(const std::vector<int>& patches) const
{
  // What an edit moves has every patch holding a copy of it in `patches`
  // (its weights are 0 on what they share with others). The first step of
  // subdivision stays inside those patches; each further step spreads by
  // a face of its level, and the frames by a finest texel: less than one
  // patch in all, so one ring. The limit stencil is the caller's
  // neighbourhood().
  return atlas_.corner_neighbourhood(patches);
}

void Multires::reconstruct(const std::vector<int>& affected)
{
  reconstruct(affected, atlas_.neighbourhood(affected));
}

void Multires::reconstruct(const std::vector<int>& affected, const PatchSet& around)
{
  Device& d = *device_;
  Runtime& rt = atlas_.runtime();
  cl::CommandQueue& q = rt.queue();
  const int finest = atlas_.max_level();
  const LevelLayout f = atlas_.layout(finest);
  const cl::Memory& fine = atlas_.level_layer(finest);
  // Levels above the edit level hold up(base) (encode() made them so, and
  // every reconstruction keeps them so on what it changes): subdividing the
  // affected set and the patches holding copies of its sides and corners
  // is enough. Decoding writes S' into the finest level, whose other texels
  // keep S as it is now, whatever changed it since the encoding (an undo, a
  // stroke elsewhere). On CPUs a finest level 2 or 3 is decoded as its
  // tiles are made, the listed patches' only (the other patches of
  // `around` need the level below, not U); otherwise U' at the finest
  // level goes into `smooth` and is decoded from there.
  const AtlasEvaluator& work = atlas_.evaluator();
  const bool as_made = tiles_as_made(atlas_);
  const int corner_base = as_made ? atlas_.subdivide_but_last_tiles(level_, around) : 0;
  if (!as_made)
    atlas_.subdivide(level_, finest, around, &d.smooth);
  const AtlasTables& tables = atlas_.tables();
  if (as_made) {
    // The kernel takes whole tiles: no edge or ring lists; what the
    // patches share with others is made while the subdivision runs.
    if (affected.empty())
      return;
    const cl::Buffer patches = device_ints(rt.context(), affected),
                     kept = device_copy(rt.context(), atlas_.shared_outside(affected));
    launch(q, finest == 2 ? d.subdivide_decode_first : d.subdivide_decode_second,
           cl::NDRange(round_up(affected.size(), kGroup)), cl::NDRange(kGroup), atlas_.level_layer(finest - 1),
           grid(atlas_.layout(finest - 1)), grid(f), patches, cl_int(affected.size()),
           tables.patch_rings(), tables.patch_across(), work.corner_work(), cl_int(corner_base), d.details, fine,
           tables.rings(), tables.slots(), d.owned, kept);
    return;
  }
  // Made while the subdivision runs.
  const PatchSet set = atlas_.patch_set(affected, Reach::All);
  const cl::Buffer patches = device_ints(rt.context(), set.patches), edges = device_ints(rt.context(), set.edges),
                   rings = device_ints(rt.context(), set.rings);
  if (f.n > 1 && !set.edges.empty())
    launch(q, d.decode_edges, cl::NDRange(round_up(set.edges.size(), kGroup)), cl::NDRange(kGroup), d.smooth,
           grid(f), tables.edges(), edges, int(set.edges.size()), d.details, work.side_work());
  if (!set.rings.empty())
    launch(q, d.decode_corners, cl::NDRange(round_up(set.rings.size(), kGroup)), cl::NDRange(kGroup), d.smooth,
           grid(f), tables.rings(), tables.slots(), rings, int(set.rings.size()), d.details, work.corner_work());
  if (!set.patches.empty()) {
    // The sides and corners shared with patches outside keep S.
    const cl::Buffer kept = device_copy(rt.context(), set.outside);
    const int count = int(set.patches.size());
    const Atlas::TileLaunch t = atlas_.tile_launch(d.decode_tiles, d.decode_patches, f, count);
    launch(q, t.kernel, t.global, t.local, d.smooth, grid(f), patches, count, d.details, fine, tables.patch_sides(),
           tables.patch_rings(), work.side_work(), work.corner_work(), kept);
  }
}

float Multires::stretch(const std::vector<int>& patches)
{
  if (patches.empty())
    return 1.f;
  Device& d = *device_;
  Runtime& rt = atlas_.runtime();
  const LevelLayout f = atlas_.layout(atlas_.max_level());
  const cl::Buffer list = device_ints(rt.context(), patches);
  launch(rt.queue(), d.patch_extent, cl::NDRange(round_up(patches.size(), kGroup)), cl::NDRange(kGroup),
         atlas_.level_layer(f.level), grid(f), list, int(patches.size()), d.extent);
  std::vector<float> now(patches.size());
  rt.queue().enqueueReadBuffer(d.extent, CL_TRUE, 0, now.size() * sizeof(float), now.data());
  float worst = 1.f;
  for (std::size_t k = 0; k < patches.size(); ++k)
    if (extent_[std::size_t(patches[k])] > 0.f)
      worst = std::max(worst, now[k] / extent_[std::size_t(patches[k])]);
  return worst;
}

void Multires::compute_base_limit(const std::vector<int>& patches)
{
  // Every texel of the patches' tiles. A patch's limit depends on the
  // control points only, so a superset gives the same bits: for many
  // patches their neighbourhood, flagged on the device at no cost to the
  // host (Atlas::neighbourhood()), instead of lists made on the host.
  const PatchSet set =
    atlas_.sets_on_device(patches.size()) ? atlas_.neighbourhood(patches) : atlas_.patch_set(patches, Reach::Any);
  atlas_.compute_limit_of(level_, device_->positions, device_->normals, set);
}

} // namespace meshpaint
