#include "paint/paint_surface.h"

#include "atlas/unfolding.h"
#include "atlas/weld.h"
#include "cl/launch.h"
#include "cl/program.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "paint/spray.h"
#include "paint/welded_smoothing.h"

#include <algorithm> // for std::sort, std::max
#include <optional>  // for std::optional
#include <cmath>     // for std::sqrt
#include <cstring>   // for std::memcpy
#include <limits>    // for std::numeric_limits

namespace meshpaint {
namespace {

constexpr std::size_t kGroup = 64;

//! A kernel's appended records: a buffer that grows to what a run needed.
struct AppendBuffer
{
  cl::Buffer records;
  std::size_t capacity = 0;
};

//! Runs a kernel over `patches` items that appends records of type Record
//! (its last three arguments: the records, two counters and the capacity)
//! and reads back what it appended, in no particular order. The counters
//! start each run at `start`; the first counts the records, the second is
//! the kernel's own. A buffer found too small grows and the kernel runs once
//! more.
template <typename Record, typename... Args>
std::vector<Record> run_appending(Runtime& rt, cl::Kernel& kernel, int patches, AppendBuffer& out,
                                  const cl::Buffer& counters, cl_int2 start, const Args&... args)
{
  cl_int count = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (out.capacity == 0) {
      out.capacity = std::min<std::size_t>(std::max(patches, 1), 4096);
      out.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(Record) * out.capacity);
    }
    rt.queue().enqueueFillBuffer(counters, start, 0, sizeof start); // no wait: the queue is in order
    launch(rt.queue(), kernel, cl::NDRange(round_up(std::size_t(patches), kGroup)), cl::NDRange(kGroup), args...,
           out.records, counters, cl_int(out.capacity));
    rt.queue().enqueueReadBuffer(counters, CL_TRUE, 0, sizeof count, &count);
    if (std::size_t(count) <= out.capacity)
      break;
    out.capacity = std::size_t(count);
    out.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(Record) * out.capacity);
  }
  std::vector<Record> records(static_cast<std::size_t>(count));
  if (count > 0)
    rt.queue().enqueueReadBuffer(out.records, CL_TRUE, 0, sizeof(Record) * std::size_t(count), records.data());
  return records;
}

//! Device bytes painting adds to the atlas at a level: the three channel
//! layers, the channel work layer, the position work layer (images only),
//! the dab weights, the patch bounds and reach bytes that the constructor
//! allocates.
std::size_t paint_bytes(const LevelLayout& l, AtlasStorage storage)
{
  return 4 * l.texels() * sizeof(Float4) + (storage == AtlasStorage::Image ? layer_bytes(l, storage) : 0) +
         l.texels() * sizeof(float) + std::size_t(l.patches) * (sizeof(cl_float4) + 1);
}

//! Why the atlas and the painting layers at `level` do not fit the device,
//! or "" when they do.
std::string paint_fit_problem(const AtlasTopology& topology, int level, const DeviceInfo& device,
                              AtlasStorage storage)
{
  const MemoryPlan plan = plan_memory(topology, level, storage);
  const std::size_t total = plan.total + paint_bytes(plan.finest, storage) +
                            WeldedSmoothing::bytes(plan.finest.texels(), topology.unique_vertices(level));
  if (total > device.global_memory)
    return format_bytes(total) + " with its paint layers, more than the device's memory (" +
           format_bytes(device.global_memory) + ")";
  return "";
}

//! Refuses a painting level whose paint layers would not fit beside the
//! atlas (which has checked its own), before they are allocated.
//! \throw ResourceError naming the largest level that fits for painting.
void check_paint_fits(Atlas& atlas, int level, const std::string& name)
{
  const DeviceInfo& device = atlas.runtime().info();
  const std::string why = paint_fit_problem(atlas.topology(), level, device, atlas.storage());
  if (why.empty())
    return;
  int fits = 0;
  while (fits < level && paint_fit_problem(atlas.topology(), fits + 1, device, atlas.storage()).empty())
    ++fits;
  throw ResourceError("painting level " + std::to_string(level) + " of '" + name + "' needs " + why + "; " +
                      (fits ? "the largest level that fits for painting is " + std::to_string(fits)
                            : std::string("not even level 1 fits for painting")));
}

} // namespace

//! Kernels that filter or copy a layer, built for one storage path.
struct PaintSurface::LayerKernels
{
  cl::Program program;
  cl::Kernel copy_tiles, gather_tiles, scatter_tiles;
  WeldedSmoothing::LayerKernels welded;

  void build(Runtime& rt, AtlasStorage storage)
  {
    program = build_program(rt,
                            std::vector<std::string>{"atlas_types.h", "atlas_access.cl", "brush.cl", "geometry.cl",
                                                     "lighting.cl"},
                            storage_options(storage, rt.info()));
    copy_tiles = cl::Kernel(program, "copy_tiles");
    welded.gather = cl::Kernel(program, "welded_gather");
    welded.scatter = cl::Kernel(program, "welded_scatter");
    gather_tiles = cl::Kernel(program, "gather_tiles");
    scatter_tiles = cl::Kernel(program, "scatter_tiles");
  }
};

//! Device state of the brush pipeline. Positions live in the atlas's
//! storage; paint channels, weights and lists are always buffers, so their
//! kernels come from a buffer build (the same one when the atlas uses
//! buffers).
struct PaintSurface::Device
{
  LayerKernels positions, channels;
  cl::Kernel brush_cull, brush_reach, paint_dab, dab_weights, move_points, move_dab, move_dab_patches;
  cl::Kernel dab_pickup;
  cl::Kernel spray_pick, spray_points;
  cl::Buffer counters, active, dab, weights;
  cl::Buffer open_sides; // brush_reach: a byte per patch
  AppendBuffer culled;   // CullRecord
  cl::Buffer unfold; // a parameter dab's PatchUnfolding per listed patch (one entry otherwise)
  std::size_t active_capacity = 0, unfold_capacity = 1;
  cl::Buffer diffuse, specular, material, channel_work;
  cl::Buffer inside_diffuse, inside_specular, inside_material; // two-sided surfaces
  cl::Buffer raster, stamp; // the stroke's pattern samples and brush image (one float when none)
  cl::Memory position_work; // image storage: a scratch layer of the finest level for moves
  std::unique_ptr<WeldedSmoothing> smoothing;
};

PaintSurface::PaintSurface(std::shared_ptr<Runtime> runtime, const BaseMesh& mesh, int level,
                           AtlasStorage storage, const BaseMaterial& material)
  : atlas_(std::make_unique<Atlas>(runtime, mesh, level, storage)), level_(level), device_(std::make_unique<Device>()),
    base_material_(material)
{
  check_paint_fits(*atlas_, level, mesh.name);
  atlas_->subdivide(1, level);
  atlas_->compute_limit();
  const LevelLayout l = atlas_->layout(level);
  Runtime& rt = atlas_->runtime();
  Device& d = *device_;
  try {
    d.positions.build(rt, storage);
    if (storage == AtlasStorage::Buffer)
      d.channels = d.positions;
    else
      d.channels.build(rt, AtlasStorage::Buffer);
    d.brush_cull = cl::Kernel(d.positions.program, "brush_cull");
    d.brush_reach = cl::Kernel(d.positions.program, "brush_reach");
    d.paint_dab = cl::Kernel(d.positions.program, "paint_dab");
    d.dab_weights = cl::Kernel(d.positions.program, "dab_weights");
    d.move_points = cl::Kernel(d.positions.program, "move_points");
    d.move_dab = cl::Kernel(d.positions.program, "move_dab");
    d.move_dab_patches = cl::Kernel(d.positions.program, "move_dab_patches");
    d.dab_pickup = cl::Kernel(d.positions.program, "dab_pickup");
    d.spray_pick = cl::Kernel(d.positions.program, "spray_pick");
    d.spray_points = cl::Kernel(d.positions.program, "spray_points");
    d.smoothing = std::make_unique<WeldedSmoothing>(rt, atlas_->topology(), d.positions.program);
    const std::size_t bytes = l.texels() * sizeof(Float4);
    d.channel_work = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.weights = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, l.texels() * sizeof(float));
    if (storage == AtlasStorage::Image)
      d.position_work = allocate_layer(rt, l, storage);
    d.diffuse = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.specular = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.material = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    const auto f4 = [](const Float4& v) { return cl_float4{{v[0], v[1], v[2], v[3]}}; };
    rt.queue().enqueueFillBuffer(d.diffuse, f4(material.diffuse), 0, bytes);
    rt.queue().enqueueFillBuffer(d.specular, f4(material.specular), 0, bytes);
    rt.queue().enqueueFillBuffer(d.material, cl_float4{{material.roughness, 0.f, 0.f, 0.f}}, 0, bytes);
    d.counters = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_int2));
    d.open_sides = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, std::size_t(l.patches));
    d.dab = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(BrushDab));
    d.unfold = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(PatchUnfolding) * d.unfold_capacity);
    rt.queue().finish();
  } catch (const cl::Error& e) {
    throw DeviceError("cannot set up painting on " + rt.info().name + ": " + describe(e));
  }
  in_stroke_.assign(std::size_t(l.patches), 0);
  open_sides_.assign(std::size_t(l.patches), 0);
  changed_at_.assign(std::size_t(l.patches), 0);
  const AtlasTopology& topo = atlas_->topology();
  neighbours_.resize(std::size_t(l.patches));
  for (int p = 0; p < l.patches; ++p)
    for (int s = 0; s < 4; ++s)
      neighbours_[std::size_t(p)][s] = topo.across(p, s);
}


std::pair<PaintSurface::LayerKernels*, const cl::Memory*> PaintSurface::layer(int id, int edit_level)
{
  Device& d = *device_;
  switch (id) {
  case kEditPositions: return {&d.positions, &atlas_->level_layer(edit_level)};
  case kPositions: return {&d.positions, &atlas_->level_layer(level_)};
  case kDiffuse: return {&d.channels, &d.diffuse};
  case kSpecular: return {&d.channels, &d.specular};
  case kInsideDiffuse: return {&d.channels, &d.inside_diffuse};
  case kInsideSpecular: return {&d.channels, &d.inside_specular};
  case kInsideMaterial: return {&d.channels, &d.inside_material};
  case kLimitPositions: return {&d.positions, &atlas_->limit_positions_layer()};
  case kLimitNormals: return {&d.positions, &atlas_->limit_normals_layer()};
  default: return {&d.channels, &d.material};
  }
}

Snapshot PaintSurface::take_snapshot(const std::vector<int>& patches, const std::vector<int>& layers, int edit_level)
{
  Snapshot s;
  s.patches = patches;
  s.layer_ids = layers;
  s.edit_level = edit_level;
  if (multires_)
    s.multires = multires_->state();
  if (patches.empty())
    return s;
  Runtime& rt = atlas_->runtime();
  const cl::Buffer list = device_ints(rt.context(), patches);
  const std::size_t most = patches.size() * std::size_t(atlas_->layout(level_).tile) * atlas_->layout(level_).tile;
  cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(Float4) * most);
  for (const int id : layers) {
    const LevelLayout l = atlas_->layout(id == kEditPositions ? edit_level : level_);
    const std::size_t n = patches.size() * std::size_t(l.tile) * l.tile;
    const auto tiles = range_tiles(l, int(patches.size()));
    const auto [kernels, memory] = layer(id, edit_level);
    launch(rt.queue(), kernels->gather_tiles, tiles.first, tiles.second, *memory, grid(l), list, int(patches.size()),
           out);
    s.layers.emplace_back(n);
    rt.queue().enqueueReadBuffer(out, CL_TRUE, 0, sizeof(Float4) * n, s.layers.back().data());
  }
  return s;
}

void PaintSurface::restore(const Snapshot& s)
{
  for (const int id : s.layer_ids) // the tiles put back may carry a mask
    mask_painted_ = mask_painted_ || id == kMaterial || id == kInsideMaterial;
  Runtime& rt = atlas_->runtime();
  const cl::Buffer list = s.patches.empty() ? cl::Buffer() : device_ints(rt.context(), s.patches);
  const auto scatter = [&](std::size_t k) {
    const int id = s.layer_ids[k];
    const LevelLayout l = atlas_->layout(id == kEditPositions ? s.edit_level : level_);
    const auto tiles = range_tiles(l, int(s.patches.size()));
    const auto [kernels, memory] = layer(id, s.edit_level);
    // Copied at creation (COPY_HOST_PTR): no wait needed for the host data.
    const cl::Buffer in(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(Float4) * s.layers[k].size(),
                        const_cast<Float4*>(s.layers[k].data()));
    launch(rt.queue(), kernels->scatter_tiles, tiles.first, tiles.second, *memory, grid(l), list,
           int(s.patches.size()), in);
  };
  const auto edit = std::find(s.layer_ids.begin(), s.layer_ids.end(), int(kEditPositions));
  if (!s.patches.empty() && edit != s.layer_ids.end()) {
    // The edit level's control points, and the levels up to the finest made
    // from them, which the next edit at that level reads around its reach.
    scatter(std::size_t(edit - s.layer_ids.begin()));
    if (s.edit_level + 1 < level_) {
      atlas_->subdivide(s.edit_level, level_ - 1, atlas_->neighbourhood_on_device(s.patches));
    }
  }
  // Then the details, before the finest level, which they leave alone.
  if (multires_) {
    if (s.memo)
      multires_->load(*s.memo);
    multires_->resume(s.multires);
  }
  if (s.patches.empty())
    return;
  changed(s.patches);
  for (std::size_t k = 0; k < s.layer_ids.size(); ++k)
    if (s.layer_ids[k] != kEditPositions)
      scatter(k);
  if (std::find(s.layer_ids.begin(), s.layer_ids.end(), int(kPositions)) != s.layer_ids.end())
    refresh_geometry(s.patches);
  rt.queue().finish();
}

void PaintSurface::phase_start()
{
  if (time_phases_) {
    atlas_->runtime().queue().finish();
    phase_clock_.restart();
  }
}

void PaintSurface::phase_done(double StepPhases::*phase)
{
  if (!time_phases_)
    return;
  atlas_->runtime().queue().finish();
  phases_.*phase += phase_clock_.ms();
  phase_clock_.restart();
}

void PaintSurface::refresh_geometry(const std::vector<int>& patches, const cl::Buffer* list)
{
  // The limit changed on the patches' sides and corners too, which every
  // patch sharing a corner with them stores: their tiles and bounds as well
  // (Atlas::neighbourhood_set(); with many patches made on the device).
  const DeviceSet set = atlas_->neighbourhood_on_device(patches, list);
  phase_done(&StepPhases::lists);
  refresh_geometry(set);
}

void PaintSurface::refresh_geometry(const DeviceSet& set)
{
  atlas_->update_limit(set); // and the patches' bounds
  phase_done(&StepPhases::limit);
}

void PaintSurface::remember(const std::vector<int>& patches)
{
  changed(patches); // every dab that changes tiles says which here, first
  if (!undo_.recording())
    return;
  std::vector<int> fresh;
  for (const int p : patches)
    if (!in_stroke_[std::size_t(p)])
      fresh.push_back(p);
  if (fresh.empty())
    return;
  Snapshot s = take_snapshot(fresh, stroke_layers_, stroke_before_.edit_level); // flags only once the tiles are safe
  for (const int p : fresh)
    in_stroke_[std::size_t(p)] = 1;
  stroke_before_.layer_ids = s.layer_ids;
  stroke_before_.patches.insert(stroke_before_.patches.end(), s.patches.begin(), s.patches.end());
  stroke_before_.layers.resize(std::max(stroke_before_.layers.size(), s.layers.size()));
  for (std::size_t k = 0; k < s.layers.size(); ++k)
    stroke_before_.layers[k].insert(stroke_before_.layers[k].end(), s.layers[k].begin(), s.layers[k].end());
}

bool PaintSurface::undo()
{
  if (!step(true))
    return false;
  undone_.push_back(std::move(history_.back()));
  history_.pop_back();
  return true;
}

bool PaintSurface::redo()
{
  if (!step(false))
    return false;
  history_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  return true;
}

bool PaintSurface::step(bool back)
{
  if (back ? !undo_.can_undo() : !undo_.can_redo())
    return false;
  // Keep the present state of the same tiles, so the step can be reversed.
  const Snapshot& target = back ? undo_.next_undo() : undo_.next_redo();
  Snapshot now = take_snapshot(target.patches, target.layer_ids, target.edit_level);
  if (target.memo && multires_) // the step puts back another encoding: keep this one for the way back
    now.memo = std::make_shared<const Multires::Memo>(multires_->save());
  restore(target);
  if (back)
    undo_.undone(std::move(now));
  else
    undo_.redone(std::move(now));
  return true;
}

PaintSurface::~PaintSurface() = default;

std::vector<CullRecord> PaintSurface::cull(const Vec3& centre, float radius)
{
  Device& d = *device_;
  const LevelLayout l = atlas_->layout(level_);
  cl_int radius_bits;
  std::memcpy(&radius_bits, &radius, sizeof radius_bits); // brush_cull's nearest distance so far
  return run_appending<CullRecord>(atlas_->runtime(), d.brush_cull, l.patches, d.culled, d.counters,
                                   cl_int2{{0, radius_bits}}, atlas_->limit_positions_layer(),
                                   atlas_->limit_normals_layer(), grid(l), l.patches, atlas_->limit_bounds(),
                                   cl_float4{{centre[0], centre[1], centre[2], 0.f}});
}

void PaintSurface::reach_sides(const Vec3& centre, float radius)
{
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  launch(rt.queue(), d.brush_reach, cl::NDRange(round_up(std::size_t(l.patches), kGroup)), cl::NDRange(kGroup),
         atlas_->limit_positions_layer(), grid(l), l.patches, atlas_->limit_bounds(),
         cl_float4{{centre[0], centre[1], centre[2], 0.f}}, radius, d.open_sides);
  rt.queue().enqueueReadBuffer(d.open_sides, CL_TRUE, 0, open_sides_.size(), open_sides_.data());
}

std::vector<int> PaintSurface::brush_patches(const Vec3& point, float radius, Vec3* centre_out, Vec3* normal_out,
                                             float reach, CullRecord* closest)
{
  if (!(reach > 0.f))
    reach = radius;
  // Snap: the closest texel within the radius is the brush centre.
  const std::vector<CullRecord> near = cull(point, radius);
  if (near.empty())
    return {};
  const CullRecord* best = &near.front();
  for (const CullRecord& c : near) // nearest, ties to the lowest patch: independent of append order
    if (c.distance < best->distance ||
        (c.distance == best->distance && c.patch < best->patch))
      best = &c;
  const float* snapped = best->closest_position;
  const Vec3 centre{snapped[0], snapped[1], snapped[2]};
  if (centre_out)
    *centre_out = centre;
  if (normal_out)
    *normal_out = {best->closest_normal[0], best->closest_normal[1], best->closest_normal[2]};
  if (closest)
    *closest = *best;

  // The brush reaches the patches connected to the centre's patch through
  // sides that themselves come within the radius: never through the air.
  const int start_patch = best->patch;
  reach_sides(centre, reach);

  // Flood from the centre's patch over the patches within reach.
  reached_.begin(open_sides_.size());
  // Breadth first: a patch waits in the queue long enough for the prefetch
  // of its neighbours to arrive (depth first pops it at once).
  // Each patch enters the queue once: room for all, and no push_back.
  std::vector<int> queue(open_sides_.size());
  std::size_t tail = 0;
  const auto visit = [&](int p) {
    if (open_sides_[std::size_t(p)] != REACH_NONE && reached_.mark(std::size_t(p))) {
      queue[tail++] = p;
      __builtin_prefetch(&neighbours_[std::size_t(p)]);
    }
  };
  visit(start_patch);
  for (std::size_t head = 0; head < tail; ++head) {
    const int p = queue[head];
    const std::uint8_t open = open_sides_[std::size_t(p)];
    for (int s = 0; s < 4; ++s)
      if ((open >> s & 1) && neighbours_[std::size_t(p)][s] >= 0)
        visit(neighbours_[std::size_t(p)][s]);
  }
  queue.resize(tail);
  return marked_in_order(std::move(queue), reached_, open_sides_.size());
}

void PaintSurface::spray(const std::vector<int>& patches, const BrushDab& dab, const Stroke& stroke,
                         std::uint64_t index)
{
  // Droplets fall evenly on the screen, so the surface gets fewer per area
  // where it is seen obliquely: by the cosine of the angle to the view.
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  const int k = stroke.spray_drops;
  std::vector<cl_float2> drops;
  for (const auto& o : spray_offsets(stroke.spray_seed, index, k, dab.radius))
    drops.push_back({{dab.screen_centre[0] + o[0] / dab.centre_depth, dab.screen_centre[1] + o[1] / dab.centre_depth}});
  const cl::Buffer drop_buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(cl_float2) * drops.size(),
                               drops.data());
  cl::Buffer keys(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_uint) * drops.size()),
    texels(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_int) * drops.size()),
    points(rt.context(), CL_MEM_WRITE_ONLY, sizeof(cl_float4) * drops.size());
  cl::CommandQueue& q = rt.queue();
  q.enqueueFillBuffer(keys, cl_uint(0xffffffffu), 0, sizeof(cl_uint) * drops.size());
  q.enqueueFillBuffer(texels, cl_int(std::numeric_limits<cl_int>::max()), 0, sizeof(cl_int) * drops.size());
  q.enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
  const cl::Buffer list = device_ints(rt.context(), patches);
  const auto tiles = range_tiles(l, int(patches.size()));
  const cl::Memory &pos = atlas_->limit_positions_layer(), &nrm = atlas_->limit_normals_layer();
  for (const int pass : {0, 1})
    launch(q, d.spray_pick, tiles.first, tiles.second, pos, nrm, grid(l), list, int(patches.size()), d.dab, atlas_->limit_bounds(),
           drop_buffer, k, pass, keys, texels);
  launch(q, d.spray_points, cl::NDRange(round_up(std::size_t(k), kGroup)), cl::NDRange(kGroup), pos, grid(l), texels, k,
         points);
  std::vector<Float4> landed(drops.size());
  q.enqueueReadBuffer(points, CL_TRUE, 0, sizeof(cl_float4) * landed.size(), landed.data());
  // Each droplet is a small object-space dab where it landed.
  Stroke droplet = stroke;
  droplet.space = SPACE_OBJECT;
  droplet.has_camera = false;
  BrushDab drop = dab;
  drop.radius = stroke.spray_size;
  for (const Float4& at : landed) {
    if (at[3] == 0.f)
      continue;
    Vec3 normal;
    const std::vector<int> hit = place(droplet, DabSample{{at[0], at[1], at[2]}, 1.f, {0.f, 0.f, 0.f}}, drop, normal);
    paint(hit, drop);
  }
}

void PaintSurface::paint(const std::vector<int>& patches, const BrushDab& dab)
{
  if (patches.empty())
    return;
  if (inside_ && (dab.alpha[CHANNEL_LABEL] > 0.f || dab.alpha[CHANNEL_DISPLACEMENT] > 0.f)) {
    // Labels and displacement belong to the surface, not to one side.
    BrushDab shared = dab, sided = dab;
    for (int c = 0; c < CHANNEL_COUNT; ++c)
      (c == CHANNEL_LABEL || c == CHANNEL_DISPLACEMENT ? sided : shared).alpha[c] = 0.f;
    inside_ = false;
    paint(patches, shared);
    inside_ = true;
    paint(patches, sided);
    return;
  }
  remember(patches);
  mask_painted_ = mask_painted_ || dab.alpha[CHANNEL_MASK] > 0.f;
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  if (d.active_capacity < patches.size()) {
    d.active_capacity = std::max(patches.size(), std::size_t(l.patches < 1024 ? l.patches : 1024));
    d.active = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(cl_int) * d.active_capacity);
  }
  // Blocking: the host memory behind both may be gone if a launch throws.
  rt.queue().enqueueWriteBuffer(d.active, CL_TRUE, 0, sizeof(cl_int) * patches.size(), patches.data());
  rt.queue().enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
  const auto tiles = range_tiles(l, int(patches.size()));
  launch(rt.queue(), d.paint_dab, tiles.first, tiles.second, atlas_->limit_positions_layer(),
         atlas_->limit_normals_layer(), grid(l), d.active, cl_int(patches.size()), d.dab, d.unfold, d.raster, d.stamp,
         diffuse_buffer(), specular_buffer(), material_buffer());
  rt.queue().finish();
  phase_done(&StepPhases::transform);
}

StrokeReport PaintSurface::apply(const Stroke& stroke, const std::vector<char>& dabs)
{
  dab_mask_ = &dabs;
  try {
    const StrokeReport r = apply(stroke);
    dab_mask_ = nullptr;
    return r;
  } catch (...) {
    dab_mask_ = nullptr;
    throw;
  }
}

float PaintSurface::distance_to(const Vec3& point, float radius)
{
  Vec3 centre;
  if (brush_patches(point, radius, &centre).empty())
    return std::numeric_limits<float>::infinity();
  const Vec3 d{centre[0] - point[0], centre[1] - point[1], centre[2] - point[2]};
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

StrokeReport PaintSurface::apply(const Stroke& stroke)
{
  // One undo step per stroke: the tiles its dabs touched, as they were; also
  // when a dab fails halfway, so that what it changed can be undone.
  // Every stroke is one step, also one that changed nothing, so that the
  // steps and history() stay in step.
  if (stroke.edit_level > level_)
    throw InputError("edit_level " + std::to_string(stroke.edit_level) + " is finer than the surface's level " +
                     std::to_string(level_));
  const auto finish_stroke = [this, &stroke] {
    for (const int p : stroke_before_.patches)
      in_stroke_[std::size_t(p)] = 0;
    if (undo_.recording())
      undo_.record(std::move(stroke_before_));
    stroke_before_ = Snapshot();
    inside_ = false;
    history_.push_back(stroke);
    undone_.clear();
  };
  // Only the layers this tool changes go into its undo step.
  switch (stroke.tool) {
  case Tool::Smooth:
    stroke_layers_ = stroke.target_colour ? std::vector<int>{kDiffuse, kSpecular} : std::vector<int>{kPositions};
    break;
  case Tool::Sculpt:
  case Tool::Inflate:
  case Tool::Flatten:
  case Tool::Grab: stroke_layers_ = {kPositions}; break;
  case Tool::Blur:
  case Tool::Smear: stroke_layers_ = {kDiffuse, kSpecular}; break;
  default: stroke_layers_ = {kDiffuse, kSpecular, kMaterial}; break;
  }
  // At a coarser edit level, its control points change too.
  const bool coarse = stroke.edit_level > 0 && stroke.edit_level < level_ && stroke_layers_.front() == kPositions;
  if (coarse)
    stroke_layers_.push_back(kEditPositions);
  stroke_before_.edit_level = coarse ? stroke.edit_level : 0;
  stroke_before_.multires = multires_ ? multires_->state() : Multires::State{};
  if (two_sided_ && stroke_layers_.front() != kPositions) // either side may change
    for (const int id : std::vector<int>(stroke_layers_))
      stroke_layers_.push_back(id + kInsideDiffuse - kDiffuse);
  StrokeReport report;
  stretched_.clear();
  stretched_marks_.begin(std::size_t(atlas_->topology().patch_count));
  encode_ms_ = 0;
  phases_ = StepPhases();
  const Timer timer;
  try {
    report = apply_dabs(stroke);
    atlas_->finish(); // the stroke's time holds all of its device work
  } catch (...) {
    finish_stroke();
    throw;
  }
  report.ms = timer.ms();
  finish_stroke();
  return report;
}

void PaintSurface::smear(const std::vector<int>& patches, BrushDab dab, std::optional<std::array<Float4, 2>>& carried)
{
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  // Lay down what the previous dab picked up, then pick up from here.
  if (carried) {
    for (int k = 0; k < 4; ++k) {
      dab.value[CHANNEL_DIFFUSE][k] = (*carried)[0][k];
      dab.value[CHANNEL_SPECULAR][k] = (*carried)[1][k];
    }
    for (int c = 0; c < CHANNEL_COUNT; ++c)
      dab.alpha[c] = c == CHANNEL_DIFFUSE || c == CHANNEL_SPECULAR ? 1.f : 0.f;
    dab.op = PAINT_OP_COPY;
    dab.pattern = PATTERN_NONE;
    paint(patches, dab);
  }
  const cl::Buffer list = device_ints(rt.context(), patches);
  const int count = int(patches.size());
  const std::size_t items = kGroup, texels = std::size_t(count) * l.tile * l.tile;
  const std::size_t groups = (texels + items - 1) / items;
  cl::Buffer partial(rt.context(), CL_MEM_WRITE_ONLY, 3 * groups * sizeof(Float4));
  rt.queue().enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
  launch(rt.queue(), d.dab_pickup, cl::NDRange(groups * items), cl::NDRange(items), atlas_->limit_positions_layer(),
         atlas_->limit_normals_layer(),
         grid(l), list, count, d.dab, d.unfold, d.stamp, diffuse_buffer(), specular_buffer(), partial,
         cl::Local(3 * items * sizeof(Float4)));
  std::vector<Float4> sums(3 * groups);
  rt.queue().enqueueReadBuffer(partial, CL_TRUE, 0, sums.size() * sizeof(Float4), sums.data());
  double acc[2][4] = {}, weight = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    for (int k = 0; k < 4; ++k) {
      acc[0][k] += sums[3 * g][k];
      acc[1][k] += sums[3 * g + 1][k];
    }
    weight += sums[3 * g + 2][0];
  }
  if (weight > 0) {
    std::array<Float4, 2> load;
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < 4; ++k)
        load[std::size_t(c)][k] = float(acc[c][k] / weight);
    carried = load;
  }
}

void PaintSurface::upload_rasters(const Stroke& stroke, BrushDab& dab)
{
  for (const Raster* r : {stroke.pattern_raster.get(), stroke.stamp.get()})
    if (r && (r->width < 1 || r->height < 1 || r->depth < 1 || r->channels < 1 || r->channels > 4 ||
              r->samples.size() != std::size_t(r->width) * r->height * r->depth * r->channels))
      throw InputError("a pattern or brush image of " + std::to_string(r->width) + "x" + std::to_string(r->height) +
                       "x" + std::to_string(r->depth) + " samples of " + std::to_string(r->channels) +
                       " channels does not match its " + std::to_string(r->samples.size()) + " values");
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const auto upload = [&](const std::vector<float>& v) {
    static const float none = 0.f;
    return cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      sizeof(float) * std::max<std::size_t>(1, v.size()), const_cast<float*>(v.empty() ? &none : v.data()));
  };
  const Raster* r = stroke.pattern_raster.get();
  d.raster = upload(r ? r->samples : std::vector<float>());
  dab.raster_size[0] = r ? r->width : 0;
  dab.raster_size[1] = r ? r->height : 0;
  dab.raster_size[2] = r ? r->depth : 0;
  dab.raster_size[3] = r ? r->channels : 0;
  // The stamp as grey: its first channel, or the mean of rgb.
  std::vector<float> grey;
  if (const Raster* s = stroke.stamp.get()) {
    const int c = s->channels;
    for (std::size_t k = 0; k + std::size_t(c) <= s->samples.size(); k += std::size_t(c))
      grey.push_back(c >= 3 ? (s->samples[k] + s->samples[k + 1] + s->samples[k + 2]) / 3.f : s->samples[k]);
    dab.stamp_size[0] = s->width;
    dab.stamp_size[1] = s->height;
  } else {
    dab.stamp_size[0] = dab.stamp_size[1] = 0;
  }
  d.stamp = upload(grey);
}

void PaintSurface::stamp_axes(const Vec3& n, const Vec3& heading, BrushDab& dab)
{
  // u: the stroke's heading in the tangent plane (or the world axis most
  // across the normal when there is none); v = n x u.
  const auto dot = [](const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  Vec3 u = heading;
  const auto project = [&](Vec3 a) {
    const float k = dot(a, n);
    return Vec3{a[0] - k * n[0], a[1] - k * n[1], a[2] - k * n[2]};
  };
  u = project(u);
  if (dot(u, u) < 1e-12f) {
    const int axis = std::fabs(n[0]) <= std::fabs(n[1]) && std::fabs(n[0]) <= std::fabs(n[2]) ? 0
                     : std::fabs(n[1]) <= std::fabs(n[2])                                  ? 1
                                                                                            : 2;
    Vec3 e{0.f, 0.f, 0.f};
    e[axis] = 1.f;
    u = project(e);
  }
  const float len = std::sqrt(dot(u, u));
  for (float& c : u)
    c /= len;
  const Vec3 v{n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
  for (int k = 0; k < 3; ++k) {
    dab.stamp_u[k] = u[k];
    dab.stamp_v[k] = v[k];
  }
}

std::vector<int> PaintSurface::place(const Stroke& stroke, const DabSample& sample, BrushDab& dab, Vec3& normal)
{
  // A tangent or screen footprint runs further than the radius in space on
  // surface turned from the brush: the search for it goes that far, at most.
  const float reach = dab.radius * (stroke.space == SPACE_SCREEN ? 4.f : stroke.space == SPACE_OBJECT ? 1.f : 2.f);
  Vec3 centre;
  CullRecord closest{};
  std::vector<int> patches = brush_patches(sample.centre, dab.radius, &centre, &normal, reach, &closest);
  if (patches.empty())
    return patches;
  for (int k = 0; k < 3; ++k)
    dab.centre[k] = centre[k];
  dab.unfolded = 0;
  if (!aim(stroke, sample.centre, normal, sample.heading, closest, dab))
    return {};
  if (stroke.space == SPACE_PARAMETER)
    return unfold_dab(closest.patch, dab);
  return patches;
}

std::vector<int> PaintSurface::unfold_dab(int centre_patch, BrushDab& dab)
{
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const Unfolding u =
    unfold(atlas_->topology(), centre_patch, atlas_->layout(level_).n, dab.centre_texel, dab.radius / dab.texel_size);
  if (d.unfold_capacity < u.maps.size()) {
    d.unfold_capacity = u.maps.size();
    d.unfold = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(PatchUnfolding) * d.unfold_capacity);
  }
  // Blocking: the host copy goes when this returns.
  rt.queue().enqueueWriteBuffer(d.unfold, CL_TRUE, 0, sizeof(PatchUnfolding) * u.maps.size(), u.maps.data());
  dab.unfolded = int(u.maps.size());
  return u.patches;
}

bool PaintSurface::aim(const Stroke& stroke, const Vec3& point, const Vec3& normal, const Vec3& heading,
                       const CullRecord& closest, BrushDab& dab)
{
  // The side a two-sided surface is painted on: the one the eye sees for a
  // screen brush, else the one the stroke's point lies on.
  const bool colours = stroke.tool == Tool::Paint || stroke.tool == Tool::Wash || stroke.tool == Tool::Dip ||
                       stroke.tool == Tool::Smear || stroke.tool == Tool::Blur ||
                       (stroke.tool == Tool::Smooth && stroke.target_colour);
  inside_ = false;
  if (two_sided_ && colours) {
    const Vec3 from = stroke.space == SPACE_SCREEN && stroke.has_camera ? stroke.camera.position : point;
    const float seen = (from[0] - dab.centre[0]) * normal[0] + (from[1] - dab.centre[1]) * normal[1] +
                       (from[2] - dab.centre[2]) * normal[2];
    inside_ = stroke.side == 2 || (stroke.side == 0 && seen < 0.f);
  }
  dab.side_sign = inside_ ? -1.f : 1.f;
  dab.space = stroke.space;
  dab.paint_backfaces = stroke.paint_backfaces ? 1 : 0;
  for (int k = 0; k < 3; ++k)
    dab.centre_normal[k] = normal[k];
  stamp_axes(normal, heading, dab);
  if (stroke.has_camera) {
    const Camera& c = stroke.camera;
    const auto sub = [](const Vec3& a, const Vec3& b) { return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    const auto dot = [](const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const auto cross = [](const Vec3& a, const Vec3& b) {
      return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    const auto unit = [&](Vec3 a) {
      const float l = std::sqrt(dot(a, a));
      return Vec3{a[0] / l, a[1] / l, a[2] / l};
    };
    const Vec3 dir = unit(sub(c.focal_point, c.position)), right = unit(cross(dir, c.view_up)),
               up = cross(right, dir);
    const Vec3 centre{dab.centre[0], dab.centre[1], dab.centre[2]}, v = sub(centre, c.position);
    const float z = dot(v, dir);
    for (int k = 0; k < 3; ++k) {
      dab.eye[k] = c.position[k];
      dab.view_dir[k] = dir[k];
      dab.view_right[k] = right[k];
      dab.view_up[k] = up[k];
    }
    dab.focal = float(1.0 / std::tan(0.5 * double(c.view_angle) * M_PI / 180.0));
    dab.centre_depth = z;
    dab.screen_centre[0] = dot(v, right) / z;
    dab.screen_centre[1] = dot(v, up) / z;
    // Screen strokes end at silhouettes: where the surface under the brush
    // turns away from the eye, or lies behind it.
    if (stroke.space == SPACE_SCREEN && (!(z > 0.f) || dab.side_sign * dot(normal, v) >= 0.f))
      return false;
  }
  if (stroke.space == SPACE_PARAMETER) {
    const LevelLayout l = atlas_->layout(level_);
    cl_float4 bound;
    atlas_->runtime().queue().enqueueReadBuffer(atlas_->limit_bounds(), CL_TRUE, sizeof(cl_float4) * closest.patch,
                                                sizeof bound, &bound);
    dab.centre_texel[0] = float(closest.closest_texel % l.tile);
    dab.centre_texel[1] = float(closest.closest_texel / l.tile);
    dab.texel_size = float(std::sqrt(2.0) * bound.s[3] / l.n); // the tile's side over its texels
  }
  return true;
}

void PaintSurface::weigh(const std::vector<int>& patches, const cl::Buffer& list, const BrushDab& dab, int level)
{
  // At a coarser edit level, on the limit of that level's control points.
  // The patches come from the finest surface, so that level's weights may
  // reach the sides they share with other patches: those stay put.
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout f = atlas_->layout(level_), l = atlas_->layout(level);
  const bool coarse = level < level_;
  const int stride = f.n / l.n;
  // The outside bits first: the blocking write below waits for the kernels
  // queued before it (a coarse edit's limit), which run meanwhile.
  cl::Buffer outside;
  if (coarse) {
    std::vector<std::uint8_t> bits = atlas_->shared_outside(patches);
    bits.resize(std::max<std::size_t>(1, bits.size())); // a valid argument when empty
    outside = cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bits.size(), bits.data());
  }
  BrushDab at_level = dab; // parameter space counts texels of the level
  for (float& c : at_level.centre_texel)
    c /= float(stride);
  at_level.texel_size *= float(stride);
  rt.queue().enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof at_level, &at_level);
  const int count = int(patches.size());
  const auto tiles = range_tiles(l, count);
  launch(rt.queue(), d.dab_weights, tiles.first, tiles.second,
         coarse ? multires_->base_positions() : atlas_->limit_positions_layer(),
         coarse ? multires_->base_normals() : atlas_->limit_normals_layer(), grid(l), list, count, d.dab, d.unfold,
         d.stamp, material_buffer(), cl_int(mask_painted_), grid(f), stride, outside,
         coarse ? multires_->base_weights() : d.weights);
}

void PaintSurface::reshape(const std::vector<int>& patches, const BrushDab& dab, const Stroke& stroke,
                           const Vec3& normal, bool reweigh)
{
  // At a coarser edit level the brush moves that level's control points and
  // the finest level is rebuilt with its details (Multires); the finest
  // patches that may change are then more than the brush's.
  const int level = stroke.edit_level > 0 ? stroke.edit_level : level_;
  const bool coarse = level < level_;
  std::vector<int> changed;
  if (coarse) {
    if (!multires_)
      multires_ = std::make_unique<Multires>(*atlas_);
    // Details persist across strokes at the same level; a stroke at the
    // finest level or at another level has them made again. Undo puts back
    // the encoding a step replaced, so a replay of what remains applied
    // encodes exactly where the session did.
    if (multires_->level() != level) {
      if (undo_.recording() && multires_->encoded_level() >= 0 && !stroke_before_.memo)
        stroke_before_.memo = std::make_shared<const Multires::Memo>(multires_->save());
      atlas_->runtime().queue().finish(); // the encoding timed alone
      const Timer encoding;
      multires_->encode(level);
      atlas_->runtime().queue().finish();
      encode_ms_ += encoding.ms();
    }
    // The edit level's limit, which the weights stand on, is computed on
    // the device while the host works out what the edit reaches (and, in
    // weigh(), which sides it shares): neither waits for the other.
    phase_done(&StepPhases::record); // the encoding, if any
    if (reweigh) {
      multires_->compute_base_limit(patches);
      phase_done(&StepPhases::weights);
    }
    changed = multires_->reach(patches);
  } else if (!stroke.target_colour && multires_) {
    multires_->detach();
  }
  remember(coarse ? changed : patches);
  phase_done(&StepPhases::record);
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  cl::CommandQueue& q = rt.queue();
  const LevelLayout l = atlas_->layout(level);
  const int count = int(patches.size());
  const cl::Buffer list = device_ints(rt.context(), patches);
  const auto tiles = range_tiles(l, count);
  const bool moves = stroke.tool == Tool::Sculpt || stroke.tool == Tool::Inflate || stroke.tool == Tool::Flatten ||
                     stroke.tool == Tool::Grab;
  // A move at the painting level weighs as it moves (move_dab); the
  // weights are kept only where something reads them again: a grab's later
  // dabs, smoothing passes, a coarse edit.
  const bool weigh_as_moved = moves && !coarse && stroke.tool != Tool::Grab;
  if (reweigh && !weigh_as_moved)
    weigh(patches, list, dab, level);
  phase_done(&StepPhases::weights);
  const cl::Buffer& weights = coarse ? multires_->base_weights() : d.weights;
  const auto geometry_done = [&] {
    if (!coarse) {
      refresh_geometry(patches, &list);
      return;
    }
    const DeviceSet around = atlas_->neighbourhood_on_device(changed);
    phase_done(&StepPhases::lists);
    multires_->reconstruct(changed, around);
    for (const int p : changed)
      if (stretched_marks_.mark(std::size_t(p)))
        stretched_.push_back(p);
    phase_done(&StepPhases::rebuild);
    refresh_geometry(around);
  };

  if (moves) {
    // A grab moves by the path's step (`normal`) times the weight.
    const int mode = stroke.tool == Tool::Inflate ? MOVE_INFLATE : stroke.tool == Tool::Flatten ? MOVE_FLATTEN
                                                                                                 : MOVE_SCULPT;
    const float amount = stroke.tool == Tool::Grab ? 1.f : stroke.amount;
    const cl::Memory& pos = atlas_->level_layer(level);
    const bool in_place = atlas_->storage() == AtlasStorage::Buffer; // see geometry.cl
    const cl::Memory& moved = in_place ? pos : d.position_work;
    const cl::Memory& normals = coarse ? multires_->base_normals() : atlas_->limit_normals_layer();
    const cl_float4 centre{{dab.centre[0], dab.centre[1], dab.centre[2], 0.f}};
    const cl_float4 towards{{normal[0], normal[1], normal[2], 0.f}};
    if (weigh_as_moved) {
      const bool plain = dab.space == SPACE_OBJECT && dab.stamp_size[0] == 0 && !mask_painted_;
      q.enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
      const Atlas::TileLaunch t = atlas_->tile_launch(d.move_dab, d.move_dab_patches, l, count);
      launch(q, t.kernel, t.global, t.local, pos, moved, atlas_->limit_positions_layer(), normals, grid(l), list,
             count, d.dab, d.unfold, d.stamp, material_buffer(), cl_int(mask_painted_), mode, amount, centre, towards,
             cl_int(plain), dab.radius, cl_int(dab.falloff), dab.strength);
    } else {
      launch(q, d.move_points, tiles.first, tiles.second, pos, moved, normals, grid(l), list, count,
             weights, mode, amount, centre, towards);
    }
    if (!in_place)
      launch(q, d.positions.copy_tiles, tiles.first, tiles.second, d.position_work, pos, grid(l), list, count);
    phase_done(&StepPhases::transform);
    geometry_done();
    return;
  }

  // Smoothing: of the control points, or of the colour channels. Edges and
  // corners are smoothed only where every patch sharing them is in the
  // brush; elsewhere their weight is zero anyway.
  const bool everything = count == l.patches;
  const PatchSet set = everything ? PatchSet() : atlas_->patch_set(patches, Reach::All);
  std::vector<std::pair<LayerKernels*, const cl::Memory*>> layers;
  if (stroke.target_colour)
    layers = {{&d.channels, &diffuse_buffer()}, {&d.channels, &specular_buffer()}};
  else
    layers = {{&d.positions, &atlas_->level_layer(level)}};
  std::vector<float> steps;
  for (int i = 0; i < stroke.iterations; ++i) {
    steps.push_back(stroke.lambda);
    if (stroke.taubin && !stroke.target_colour)
      steps.push_back(stroke.mu);
  }
  for (const auto& [k, layer] : layers)
    d.smoothing->run(k->welded, *layer, l, everything ? nullptr : &set, weights, steps);
  phase_done(&StepPhases::transform);
  if (stroke.target_colour)
    q.finish();
  else
    geometry_done();
}

StrokeReport PaintSurface::apply_dabs(const Stroke& stroke)
{
  phase_start();
  StrokeReport report;
  BrushDab dab{};
  dab.side_sign = 1.f;
  dab.falloff = stroke.falloff;
  dab.op = stroke.op;
  for (int c = 0; c < CHANNEL_COUNT; ++c) {
    for (int k = 0; k < 4; ++k)
      dab.value[c][k] = stroke.value[c][k];
    dab.alpha[c] = stroke.alpha[c];
  }
  if (stroke.remover) { // the underlying material, copied back
    const BaseMaterial& m = base_material_;
    for (int k = 0; k < 4; ++k) {
      dab.value[CHANNEL_DIFFUSE][k] = m.diffuse[k];
      dab.value[CHANNEL_SPECULAR][k] = m.specular[k];
      dab.value[CHANNEL_ROUGHNESS][k] = k < 3 ? m.roughness : 1.f;
      dab.value[CHANNEL_DISPLACEMENT][k] = k < 3 ? 0.f : 1.f;
    }
    dab.op = PAINT_OP_COPY;
  }
  dab.specular_coefficient = stroke.specular_coefficient;
  dab.pattern = stroke.pattern;
  dab.pattern_coord = stroke.pattern_coord;
  dab.matte = stroke.matte;
  dab.octaves = stroke.octaves;
  for (int k = 0; k < 12; ++k)
    dab.pattern_transform[k] = stroke.pattern_transform[std::size_t(k)];
  if ((stroke.pattern == PATTERN_IMAGE || stroke.pattern == PATTERN_VOLUME) &&
      (!stroke.pattern_raster || stroke.pattern_raster->empty()))
    throw InputError("the stroke's " + std::string(stroke.pattern == PATTERN_IMAGE ? "image" : "volume") +
                     " pattern has no samples (load '" + stroke.pattern_file + "' first)");
  if (!stroke.stamp_file.empty() && (!stroke.stamp || stroke.stamp->empty()))
    throw InputError("the stroke's brush image has no samples (load '" + stroke.stamp_file + "' first)");
  upload_rasters(stroke, dab);
  try {
    if (stroke.tool == Tool::Wash || stroke.tool == Tool::Dip) {
      std::vector<int> all(std::size_t(atlas_->topology().patch_count));
      for (std::size_t p = 0; p < all.size(); ++p)
        all[p] = int(p);
      dab.radius = std::numeric_limits<float>::infinity();
      dab.strength = stroke.strength;
      dab.falloff = FALLOFF_CONSTANT;
      inside_ = two_sided_ && stroke.side == 2; // a wash covers the outside unless told
      paint(all, dab);
      report.dabs = report.dabs_applied = 1;
      report.patches_touched = all.size();
      return report;
    }
    if (stroke.tool == Tool::Grab) {
      grab(stroke, dab, report);
      report.stretch = stroke_stretch();
      report.encode_ms = encode_ms_;
      report.phases = phases_;
      return report;
    }
    // The mirror plane passes through the centre of the base mesh's bounds.
    const BaseMesh& base = atlas_->base_mesh();
    float mirror_at = 0.f;
    if (stroke.mirror_axis >= 0) {
      float lo = base.points.front()[stroke.mirror_axis], hi = lo;
      for (const Vec3& p : base.points) {
        lo = std::min(lo, p[stroke.mirror_axis]);
        hi = std::max(hi, p[stroke.mirror_axis]);
      }
      mirror_at = 0.5f * (lo + hi);
    }
    std::optional<std::array<Float4, 2>> carried[2]; // the smear brush's load per side of the mirror
    const std::vector<DabSample> samples = stroke_samples(stroke);
    for (std::size_t index = 0; index < samples.size(); ++index) {
      const DabSample& sample = samples[index];
      if (dab_mask_ && (index >= dab_mask_->size() || !(*dab_mask_)[index])) // another object's dab
        continue;
      // The dab, and with a mirror its reflection (heading reflected too).
      std::vector<DabSample> dabs{sample};
      if (stroke.mirror_axis >= 0) {
        DabSample m = sample;
        m.centre[stroke.mirror_axis] = 2.f * mirror_at - m.centre[stroke.mirror_axis];
        m.heading[stroke.mirror_axis] = -m.heading[stroke.mirror_axis];
        dabs.push_back(m);
      }
      dab.radius = stroke.radius * sample.pressure;
      dab.strength = stroke.strength * sample.pressure;
      bool on_surface = false;
      for (std::size_t side = 0; side < dabs.size(); ++side) {
        ++report.dabs;
        if (!(dab.radius > 0.f))
          continue;
        Vec3 normal;
        phase_start();
        const std::vector<int> patches = place(stroke, dabs[side], dab, normal);
        phase_done(&StepPhases::place);
        if (patches.empty())
          continue;
        on_surface = true;
        if (stroke.tool == Tool::Smear)
          smear(patches, dab, carried[side]);
        else if (stroke.spray_drops > 0)
          spray(patches, dab, stroke, report.dabs);
        else if (stroke.tool == Tool::Paint || stroke.tool == Tool::Label)
          paint(patches, dab);
        else
          reshape(patches, dab, stroke, normal);
        ++report.dabs_applied;
        report.patches_touched += patches.size();
      }
      // Zero pressure skips a dab, no surface ends the stroke (in a scene,
      // the scene decides that).
      if (!on_surface && dab.radius > 0.f && !dab_mask_) {
        report.left_surface = true;
        break;
      }
    }
  } catch (const cl::Error& e) {
    throw DeviceError("painting failed on " + atlas_->runtime().info().name + ": " + describe(e));
  }
  report.stretch = stroke_stretch();
  report.encode_ms = encode_ms_;
  report.phases = phases_;
  return report;
}

float PaintSurface::stroke_stretch()
{
  if (stretched_.empty())
    return 1.f;
  phase_start();
  const float worst = multires_->stretch(stretched_);
  phase_done(&StepPhases::rebuild);
  return worst;
}

void PaintSurface::grab(const Stroke& stroke, BrushDab& dab, StrokeReport& report)
{
  // The region under the first point is taken once; every later dab moves
  // it by the path's step, with the weights it had when taken.
  std::vector<DabSample> samples = stroke_samples(stroke);
  if (stroke.points.size() > 1 && samples.back().centre != stroke.points.back()) // the pull ends at the path's end
    samples.push_back({stroke.points.back(), stroke.pressure.empty() ? 1.f : stroke.pressure.back()});
  report.dabs = samples.size();
  if (dab_mask_ && (dab_mask_->empty() || !dab_mask_->front())) // in a scene, the region is another object's
    return;
  dab.radius = stroke.radius * samples.front().pressure;
  dab.strength = stroke.strength * samples.front().pressure;
  if (!(dab.radius > 0.f))
    return;
  Vec3 normal;
  phase_start();
  const std::vector<int> patches = place(stroke, samples.front(), dab, normal);
  phase_done(&StepPhases::place);
  if (patches.empty()) {
    report.left_surface = true;
    return;
  }
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const Vec3& a = samples[k - 1].centre;
    const Vec3& b = samples[k].centre;
    reshape(patches, dab, stroke, Vec3{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, k == 1);
    ++report.dabs_applied;
    report.patches_touched += patches.size();
  }
}

void PaintSurface::geometry_changed()
{
  changed_all();
  if (multires_)
    multires_->invalidate();
  atlas_->compute_limit(); // and the bounds
  atlas_->finish();
}

std::vector<float> PaintSurface::scattered_light(const Vec3& light, int passes)
{
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  cl::CommandQueue& q = rt.queue();
  const LevelLayout l = atlas_->layout(level_);
  const float len = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  if (!(len > 0.f))
    throw InputError("the light's direction must not be zero");
  try {
    cl::Kernel irradiance(d.positions.program, "irradiance");
    const auto tiles = range_tiles(l, l.patches);
    launch(q, irradiance, tiles.first, tiles.second, atlas_->limit_normals_layer(), grid(l), l.patches,
           cl_float4{{light[0] / len, light[1] / len, light[2] / len, 0.f}}, d.channel_work);
    // Diffusion over the whole surface: the smoothing passes at full weight.
    q.enqueueFillBuffer(d.weights, 1.f, 0, l.texels() * sizeof(float));
    const std::vector<Float4> welded = d.smoothing->run_welded(d.channels.welded, d.channel_work, l, d.weights,
                                                               std::vector<float>(std::size_t(passes), 0.5f));
    std::vector<float> out(welded.size());
    for (std::size_t v = 0; v < welded.size(); ++v)
      out[v] = welded[v][0];
    return out;
  } catch (const cl::Error& e) {
    throw DeviceError("the subsurface light failed on " + rt.info().name + ": " + describe(e));
  }
}

PaintChannels PaintSurface::read_channels()
{
  const std::size_t n = atlas_->layout(level_).texels();
  PaintChannels c;
  c.diffuse.resize(n);
  c.specular.resize(n);
  c.material.resize(n);
  cl::CommandQueue& q = atlas_->runtime().queue();
  q.enqueueReadBuffer(device_->diffuse, CL_TRUE, 0, n * sizeof(Float4), c.diffuse.data());
  q.enqueueReadBuffer(device_->specular, CL_TRUE, 0, n * sizeof(Float4), c.specular.data());
  q.enqueueReadBuffer(device_->material, CL_TRUE, 0, n * sizeof(Float4), c.material.data());
  if (two_sided_) {
    for (auto [from, to] : {std::pair{&device_->inside_diffuse, &c.inside_diffuse},
                            std::pair{&device_->inside_specular, &c.inside_specular},
                            std::pair{&device_->inside_material, &c.inside_material}}) {
      to->resize(n);
      q.enqueueReadBuffer(*from, CL_TRUE, 0, n * sizeof(Float4), to->data());
    }
  }
  return c;
}

cl::Buffer& PaintSurface::diffuse_buffer() { return inside_ ? device_->inside_diffuse : device_->diffuse; }
cl::Buffer& PaintSurface::specular_buffer() { return inside_ ? device_->inside_specular : device_->specular; }
cl::Buffer& PaintSurface::material_buffer() { return inside_ ? device_->inside_material : device_->material; }

void PaintSurface::set_two_sided(bool on)
{
  if (on == two_sided_)
    return;
  display_ = nullptr; // made again with (or without) the inside's arrays
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const std::size_t bytes = atlas_->layout(level_).texels() * sizeof(Float4);
  if (on) {
    try {
      d.inside_diffuse = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
      d.inside_specular = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
      d.inside_material = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
      const auto f4 = [](const Float4& v) { return cl_float4{{v[0], v[1], v[2], v[3]}}; };
      rt.queue().enqueueFillBuffer(d.inside_diffuse, f4(base_material_.diffuse), 0, bytes);
      rt.queue().enqueueFillBuffer(d.inside_specular, f4(base_material_.specular), 0, bytes);
      rt.queue().enqueueFillBuffer(d.inside_material, cl_float4{{base_material_.roughness, 0.f, 0.f, 0.f}}, 0, bytes);
      rt.queue().finish();
    } catch (const cl::Error& e) {
      throw DeviceError("cannot add the inside channels on " + rt.info().name + ": " + describe(e));
    }
  } else {
    d.inside_diffuse = d.inside_specular = d.inside_material = cl::Buffer();
  }
  two_sided_ = on;
  changed_all();
  // Steps recorded for the other number of layers cannot be undone.
  UndoLog fresh(undo_.budget());
  fresh.set_recording(undo_.recording());
  undo_ = std::move(fresh);
}

void PaintSurface::write_channels(const PaintChannels& c)
{
  changed_all();
  const std::size_t n = atlas_->layout(level_).texels();
  if (c.diffuse.size() != n || c.specular.size() != n || c.material.size() != n)
    throw InputError("channel layers of " + std::to_string(c.diffuse.size()) + " texels do not fit a level-" +
                     std::to_string(level_) + " atlas of " + std::to_string(n));
  cl::CommandQueue& q = atlas_->runtime().queue();
  q.enqueueWriteBuffer(device_->diffuse, CL_TRUE, 0, n * sizeof(Float4), c.diffuse.data());
  q.enqueueWriteBuffer(device_->specular, CL_TRUE, 0, n * sizeof(Float4), c.specular.data());
  q.enqueueWriteBuffer(device_->material, CL_TRUE, 0, n * sizeof(Float4), c.material.data());
  const auto masks = [](const std::vector<Float4>& material) {
    return std::any_of(material.begin(), material.end(), [](const Float4& m) { return m[3] != 0.f; });
  };
  mask_painted_ = masks(c.material) || masks(c.inside_material);
  if (c.inside_diffuse.empty())
    return;
  if (c.inside_diffuse.size() != n || c.inside_specular.size() != n || c.inside_material.size() != n)
    throw InputError("inside channel layers of " + std::to_string(c.inside_diffuse.size()) +
                     " texels do not fit a level-" + std::to_string(level_) + " atlas of " + std::to_string(n));
  set_two_sided(true);
  q.enqueueWriteBuffer(device_->inside_diffuse, CL_TRUE, 0, n * sizeof(Float4), c.inside_diffuse.data());
  q.enqueueWriteBuffer(device_->inside_specular, CL_TRUE, 0, n * sizeof(Float4), c.inside_specular.data());
  q.enqueueWriteBuffer(device_->inside_material, CL_TRUE, 0, n * sizeof(Float4), c.inside_material.data());
}

} // namespace meshpaint
