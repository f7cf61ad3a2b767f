#include "atlas/atlas.h"

#include "cl/launch.h"
#include "cl/kernel_programs.h"
#include "core/errors.h"
#include "core/format.h"
#include "mesh/far_refiner.h"
#include "mesh/spatial_order.h"

#include <algorithm> // for std::max, std::sort, std::unique, std::binary_search
#include <cmath>     // for std::cos, std::sin, std::sqrt
#include <cstdlib>   // for std::getenv
#include <stdexcept> // for std::logic_error

namespace meshpaint {
namespace {

// Work-group shapes: a few whole tiles for the atlas-wide kernels, runs of
// edges or rings for the table-driven ones.
constexpr std::size_t kGroupTexels = 256, kGroup1D = 64;
const cl::NDRange kLocalEdges(1, kGroup1D), kLocal1D(kGroup1D);

cl::NDRange range_edges(int positions, int edges)
{
  return cl::NDRange(positions, round_up(edges, kGroup1D));
}
cl::NDRange range1d(int items) { return cl::NDRange(round_up(items, kGroup1D)); }


//! Calls f(patch-major index, atlas-image index) for the first texel of every
//! tile row.
template <typename F>
void for_each_tile_row(const LevelLayout& l, F&& f)
{
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.tile; ++j)
      f(l.index(p, 0, j), std::size_t((p / l.tiles_x) * l.tile + j) * l.width + (p % l.tiles_x) * l.tile);
}

//! `count` squares of side x side work items, stacked along the second axis.
std::pair<cl::NDRange, cl::NDRange> range_squares(std::size_t side, int count)
{
  if (side > kGroupTexels)
    return {cl::NDRange(side, side * std::size_t(count)), cl::NullRange};
  const std::size_t rows = std::max<std::size_t>(1, kGroupTexels / side);
  return {cl::NDRange(side, round_up(side * std::size_t(count), rows)), cl::NDRange(side, rows)};
}

} // namespace

std::pair<cl::NDRange, cl::NDRange> range_tiles(const LevelLayout& l, int count)
{
  return range_squares(std::size_t(l.tile), count);
}

Atlas::TileLaunch Atlas::tile_launch(cl::Kernel& per_texel, cl::Kernel& per_patch, const LevelLayout& l,
                                     int count) const
{
  if (patch_items_)
    return {per_patch, range1d(count), kLocal1D};
  const auto tiles = range_tiles(l, count);
  return {per_texel, tiles.first, tiles.second};
}

std::pair<cl::NDRange, cl::NDRange> range_interiors(const LevelLayout& l, int count)
{
  return range_squares(std::size_t(l.n - 1), count);
}

AtlasStorage parse_storage(const std::string& name)
{
  if (name == "buffer")
    return AtlasStorage::Buffer;
  if (name == "image")
    return AtlasStorage::Image;
  throw InputError("unknown atlas storage '" + name + "' (buffer or image)");
}

std::string storage_options(AtlasStorage storage, const DeviceInfo& device)
{
  if (storage == AtlasStorage::Image)
    return "-cl-std=CL1.2 -D ATLAS_IMAGE";
  return device.gpu ? "-cl-std=CL1.2" : "-cl-std=CL1.2 -D ATLAS_PREFETCH";
}

const char* storage_name(AtlasStorage storage)
{
  return storage == AtlasStorage::Image ? "image" : "buffer";
}

AtlasStorage default_storage(const DeviceInfo& device)
{
  if (const char* env = std::getenv("MESHPAINT_STORAGE"); env && *env)
    return parse_storage(env);
  return device.gpu && device.images ? AtlasStorage::Image : AtlasStorage::Buffer;
}

std::size_t layer_bytes(const LevelLayout& l, AtlasStorage storage)
{
  return 16 * (storage == AtlasStorage::Image ? l.image_texels() : l.texels());
}

//! Bytes of the whole-tile kernels' tables and the compact results of the
//! side and corner kernels at a level.
std::size_t border_work_bytes(const AtlasTopology& topo, const LevelLayout& l)
{
  return std::size_t(topo.patch_count) * 2 * sizeof(cl_int4) +
         (topo.edges.size() * std::size_t(l.n - 1) + topo.rings.size()) * 2 * sizeof(cl_float4);
}

MemoryPlan plan_memory(const AtlasTopology& topology, int level, AtlasStorage storage)
{
  MemoryPlan plan;
  for (int l = 1; l <= level; ++l)
    plan.total += layer_bytes(level_layout(topology.patch_count, l), storage);
  plan.finest = level_layout(topology.patch_count, level);
  plan.largest_allocation = layer_bytes(plan.finest, storage);
  plan.total += 2 * plan.largest_allocation; // limit positions and normals
  plan.total += border_work_bytes(topology, plan.finest);
  plan.total += topology.edges.size() * sizeof(PatchEdge) +
                topology.rings.size() * sizeof(CornerRing) +
                topology.slots.size() * sizeof(CornerSlot);
  return plan;
}

//! One float4 layer of one level.
struct Atlas::Layer
{
  cl::Buffer buffer;
  cl::Image2D image;
  const cl::Memory& mem() const
  {
    return image() ? static_cast<const cl::Memory&>(image) : static_cast<const cl::Memory&>(buffer);
  }
};

//! The built program and its kernels, for one storage path.
struct Atlas::Kernels
{
  cl::Program program;
  cl::Kernel subdivide_tiles, subdivide_patches, subdivide_edges, subdivide_corners;
  cl::Kernel limit_tiles, limit_patches, limit_edges, limit_corners, patch_bounds;
  cl::Kernel reduce_interior, reduce_edges, reduce_corners;
  cl::Buffer edges, rings, slots;
  cl::Buffer valences; // limit_corners' constants per valence (limit_constants())
  // The whole-tile kernels' tables (border_tables()), and the side and
  // corner kernels' results (a position and a normal for the limit), sized
  // for the finest level.
  cl::Buffer patch_sides, patch_rings, side_work, corner_work;
  // Sets worked out on the device (select.cl): a byte per patch, edge and
  // ring, and the generation of the last set.
  cl::Kernel flag_corners, flag_ring_patches, flag_borders;
  cl::Buffer patch_flags, edge_flags, ring_flags;
  std::uint8_t generation = 0;
};

namespace {

//! The corner limit masks' constants for every valence m the rings have, in
//! double precision: two float4 per m, for an interior vertex
//! (cos 2pi/m, sin 2pi/m, lambda, 1 / (4 lambda - 1)) and for a boundary one
//! (cos pi/m, sin pi/m, 1 / (m (3 + cos pi/m)), (cos pi/m + 1) / sin pi/m).
std::vector<Float4> limit_constants(const AtlasTopology& topo)
{
  int most = 1;
  for (const CornerRing& r : topo.rings)
    most = std::max(most, int(r.count));
  std::vector<Float4> out(2 * std::size_t(most + 1), Float4{0.f, 0.f, 0.f, 0.f});
  for (int m = 1; m <= most; ++m) {
    const double theta = 2.0 * M_PI / m, c = std::cos(theta), ch = std::cos(0.5 * theta);
    const double lambda = 0.3125 + 0.0625 * (c + ch * std::sqrt(2.0 * (9.0 + c)));
    out[2 * std::size_t(m)] = {float(c), float(std::sin(theta)), float(lambda), float(1.0 / (4.0 * lambda - 1.0))};
    const double half = M_PI / m, bc = std::cos(half), bs = std::sin(half);
    out[2 * std::size_t(m) + 1] = {float(bc), float(bs), float(1.0 / (m * (3.0 + bc))),
                                   float(bs != 0.0 ? (bc + 1.0) / bs : 0.0)};
  }
  return out;
}

//! Per patch, for the whole-tile kernels: each side's edge as 2 * edge + (1
//! when the patch is the edge's second), and each corner's ring in the
//! device table.
std::pair<std::vector<std::array<int, 4>>, std::vector<std::array<int, 4>>>
border_tables(const AtlasTopology& topo, const std::vector<int>& device_ring)
{
  std::vector<std::array<int, 4>> sides(std::size_t(topo.patch_count)), rings(sides.size());
  for (std::size_t p = 0; p < sides.size(); ++p)
    for (int c = 0; c < 4; ++c) {
      const int e = topo.patch_sides[p][std::size_t(c)];
      const PatchEdge& edge = topo.edges[std::size_t(e)];
      sides[p][std::size_t(c)] = 2 * e + (edge.patch[0] == int(p) && edge.side[0] == c ? 0 : 1);
      rings[p][std::size_t(c)] = device_ring[std::size_t(topo.patch_corners[p][std::size_t(c)])];
    }
  return {sides, rings};
}

} // namespace

std::string fit_problem(const AtlasTopology& topo, int level, const DeviceInfo& device, AtlasStorage storage)
{
  const MemoryPlan plan = plan_memory(topo, level, storage);
  const LevelLayout& l = plan.finest;
  if (storage == AtlasStorage::Image &&
      (std::size_t(l.width) > device.image_max_width || std::size_t(l.height) > device.image_max_height))
    return "an atlas of " + std::to_string(l.width) + "x" + std::to_string(l.height) +
           " texels, larger than the device's largest image (" +
           std::to_string(device.image_max_width) + "x" + std::to_string(device.image_max_height) + ")";
  if (std::max(l.texels(), l.image_texels()) >= (std::size_t(1) << 31))
    return std::to_string(l.texels()) + " texels, more than 2^31 (32-bit texel indices)";
  if (plan.largest_allocation > device.max_allocation)
    return format_bytes(plan.largest_allocation) + " in one layer, more than the device's largest "
           "allocation (" + format_bytes(device.max_allocation) + ")";
  if (plan.total > device.global_memory)
    return format_bytes(plan.total) + " in all, more than the device's memory (" +
           format_bytes(device.global_memory) + ")";
  return "";
}

AtlasTopology atlas_topology_of(const BaseMesh& mesh)
{
  auto refiner = make_refiner(mesh);
  refine_uniform(*refiner, 1, true);
  return build_atlas_topology(refiner->GetLevel(1));
}

int largest_fitting_level(const AtlasTopology& topology, const DeviceInfo& device, AtlasStorage storage)
{
  int fits = 0;
  while (fits < kMaxLevel && fit_problem(topology, fits + 1, device, storage).empty())
    ++fits;
  return fits;
}

Atlas::Atlas(std::shared_ptr<Runtime> runtime, const BaseMesh& mesh, int max_level,
             AtlasStorage storage)
  : runtime_(std::move(runtime)), storage_(storage), max_level_(max_level)
{
  if (max_level < 1 || max_level > kMaxLevel)
    throw InputError("level " + std::to_string(max_level) + " is out of range (1.." +
                     std::to_string(kMaxLevel) + ")");
  const DeviceInfo& device = runtime_->info();
  if (storage_ == AtlasStorage::Image && !device.images)
    throw DeviceError(device.name + " has no image support; use buffer storage");

  base_ = spatially_ordered(mesh, &base_face_order_);
  auto refiner = make_refiner(base_);
  refine_uniform(*refiner, 1, true); // full topology: edges and vertex rings
  topology_ = build_atlas_topology(refiner->GetLevel(1));

  if (const std::string why = fit_problem(topology_, max_level, device, storage_); !why.empty()) {
    const int fits = largest_fitting_level(topology_, device, storage_);
    throw ResourceError("level " + std::to_string(max_level) + " of '" + mesh.name + "' needs " +
                        why + "; " +
                        (fits ? "the largest level that fits is " + std::to_string(fits)
                              : std::string("not even level 1 fits")));
  }

  // Level 1: the first Catmull-Clark step, one 2x2 tile per quad.
  const std::vector<Vec3> level1 = interpolate_levels(*refiner, base_.points)[1];
  const LevelLayout l1 = layout(1);
  std::vector<Float4> texels(l1.texels(), Float4{0.f, 0.f, 0.f, 0.f});
  static const int corner_xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int p = 0; p < topology_.patch_count; ++p)
    for (int c = 0; c < 4; ++c) {
      const Vec3& v = level1[topology_.patch_corners[p][c]];
      texels[l1.index(p, corner_xy[c][0], corner_xy[c][1])] = {v[0], v[1], v[2], 0.f};
    }

  try {
    for (int l = 1; l <= max_level_; ++l)
      levels_.push_back(make_layer(layout(l)));
    write_layer(levels_[0], l1, texels);

    kernels_ = std::make_unique<Kernels>();
    Kernels& k = *kernels_;
    k.program = kernel_program(*runtime_, KernelProgram::Atlas, storage_options(storage_, runtime_->info()));
    k.subdivide_tiles = cl::Kernel(k.program, "subdivide_tiles");
    k.subdivide_patches = cl::Kernel(k.program, "subdivide_patches");
    k.subdivide_edges = cl::Kernel(k.program, "subdivide_edges");
    k.subdivide_corners = cl::Kernel(k.program, "subdivide_corners");
    k.limit_tiles = cl::Kernel(k.program, "limit_tiles");
    k.limit_patches = cl::Kernel(k.program, "limit_patches");
    patch_items_ = !runtime_->info().gpu;
    k.limit_edges = cl::Kernel(k.program, "limit_edges");
    k.limit_corners = cl::Kernel(k.program, "limit_corners");
    k.patch_bounds = cl::Kernel(k.program, "patch_bounds");
    k.flag_corners = cl::Kernel(k.program, "flag_corners");
    k.flag_ring_patches = cl::Kernel(k.program, "flag_ring_patches");
    k.flag_borders = cl::Kernel(k.program, "flag_borders");
    k.reduce_interior = cl::Kernel(k.program, "reduce_interior");
    k.reduce_edges = cl::Kernel(k.program, "reduce_edges");
    k.reduce_corners = cl::Kernel(k.program, "reduce_corners");
    const auto upload = [&](const auto& v) {
      return cl::Buffer(runtime_->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        std::max<std::size_t>(1, v.size() * sizeof(v[0])),
                        const_cast<void*>(static_cast<const void*>(v.data())));
    };
    // The corner kernel visits rings in the order of their first patch, so
    // it sweeps the atlas instead of jumping (measured: ~8% faster on the
    // bunny at level 3). Edges stay in OpenSubdiv's order, which measured
    // better than sorting them by patch.
    std::vector<int> order(topology_.rings.size());
    for (std::size_t v = 0; v < order.size(); ++v)
      order[v] = int(v);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return topology_.slots[topology_.rings[a].first].patch < topology_.slots[topology_.rings[b].first].patch;
    });
    std::vector<CornerRing> rings;
    device_ring_.assign(order.size(), -1);
    for (std::size_t k = 0; k < order.size(); ++k) {
      rings.push_back(topology_.rings[order[k]]);
      device_ring_[order[k]] = int(k);
    }
    k.edges = upload(topology_.edges);
    k.rings = upload(rings);
    k.valences = upload(limit_constants(topology_));
    k.slots = upload(topology_.slots);
    const auto [patch_sides, patch_rings] = border_tables(topology_, device_ring_);
    k.patch_sides = upload(patch_sides);
    k.patch_rings = upload(patch_rings);
    const LevelLayout finest = layout(max_level_);
    k.side_work = cl::Buffer(runtime_->context(), CL_MEM_READ_WRITE,
                               std::max<std::size_t>(1, topology_.edges.size() * std::size_t(finest.n - 1)) *
                                   2 * sizeof(cl_float4));
    k.corner_work =
        cl::Buffer(runtime_->context(), CL_MEM_READ_WRITE, topology_.rings.size() * 2 * sizeof(cl_float4));
    const auto flags = [&](std::size_t n) {
      const std::size_t bytes = round_up(std::max<std::size_t>(1, n), sizeof(cl_uint)); // whole fill patterns
      cl::Buffer b(runtime_->context(), CL_MEM_READ_WRITE, bytes);
      runtime_->queue().enqueueFillBuffer(b, cl_uint(0), 0, bytes);
      return b;
    };
    k.patch_flags = flags(std::size_t(topology_.patch_count));
    k.edge_flags = flags(topology_.edges.size());
    k.ring_flags = flags(topology_.rings.size());
  } catch (const cl::Error& e) {
    throw DeviceError("cannot set up the atlas on " + device.name + ": " + describe(e));
  }
}

Atlas::~Atlas() = default;

LevelLayout Atlas::layout(int level) const { return level_layout(topology_.patch_count, level); }

cl::Memory allocate_layer(Runtime& runtime, const LevelLayout& l, AtlasStorage storage)
{
  // Zero-filled, so texels of unused image tiles are defined.
  const cl_float4 zero{{0.f, 0.f, 0.f, 0.f}};
  if (storage == AtlasStorage::Image) {
    cl::Image2D image(runtime.context(), CL_MEM_READ_WRITE, cl::ImageFormat(CL_RGBA, CL_FLOAT), l.width, l.height);
    runtime.queue().enqueueFillImage(image, zero, {0, 0, 0}, {std::size_t(l.width), std::size_t(l.height), 1});
    return std::move(image);
  }
  cl::Buffer buffer(runtime.context(), CL_MEM_READ_WRITE, layer_bytes(l, storage));
  runtime.queue().enqueueFillBuffer(buffer, zero, 0, layer_bytes(l, storage));
  return std::move(buffer);
}

Atlas::Layer Atlas::make_layer(const LevelLayout& l)
{
  const cl::Memory memory = allocate_layer(*runtime_, l, storage_);
  Layer layer;
  if (storage_ == AtlasStorage::Image)
    layer.image = cl::Image2D(memory(), true);
  else
    layer.buffer = cl::Buffer(memory(), true);
  return layer;
}

void Atlas::subdivide(int from_level, int to_level) { subdivide(from_level, to_level, nullptr); }

void Atlas::subdivide(int from_level, int to_level, const PatchSet* set, const cl::Memory* last)
{
  subdivide(from_level, to_level, device_set(set), last);
}

void Atlas::subdivide(int from_level, int to_level, const DeviceSet& set, const cl::Memory* last)
{
  if (from_level < 1 || to_level > max_level_ || from_level > to_level)
    throw InputError("cannot subdivide from level " + std::to_string(from_level) + " to " +
                     std::to_string(to_level) + " (atlas levels 1.." + std::to_string(max_level_) + ")");
  check_current(set);
  Kernels& k = *kernels_;
  cl::CommandQueue& q = runtime_->queue();
  const cl::Buffer &patch_list = set.patches, &edge_list = set.edges, &ring_list = set.rings;
  const int patches = set.patch_count, edges = set.edge_count, rings = set.ring_count;
  const cl_int generation = set.generation;
  if (to_level == max_level_ && from_level < to_level && !last)
    limit_current_ = false;
  for (int l = from_level; l < to_level; ++l) {
    const LevelLayout s = layout(l), d = layout(l + 1);
    const cl::Memory &in = levels_[l - 1].mem(), &out = last && l + 1 == to_level ? *last : levels_[l].mem();
    if (edges > 0)
      launch(q, k.subdivide_edges, range1d(edges), kLocal1D, in, k.side_work, k.edges, edge_list, edges,
             set.edge_flags, generation, grid(s), grid(d));
    if (rings > 0)
      launch(q, k.subdivide_corners, range1d(rings), kLocal1D, in, k.corner_work, k.rings, k.slots, ring_list, rings,
             set.ring_flags, generation, grid(s));
    if (patches > 0) {
      const TileLaunch t = tile_launch(k.subdivide_tiles, k.subdivide_patches, d, patches);
      launch(q, t.kernel, t.global, t.local, in, out, grid(s), grid(d), patch_list, patches, set.patch_flags,
             generation, k.patch_sides, k.patch_rings, k.side_work, k.corner_work);
    }
  }
  // No wait: a list released here lives on until the kernels using it end,
  // and the host goes on with its next sets while they run.
}

void Atlas::reduce(int from_level, int to_level)
{
  if (to_level < 1 || from_level > max_level_ || to_level > from_level)
    throw InputError("cannot reduce from level " + std::to_string(from_level) + " to " +
                     std::to_string(to_level) + " (atlas levels 1.." + std::to_string(max_level_) + ")");
  Kernels& k = *kernels_;
  cl::CommandQueue& q = runtime_->queue();
  const int edges = int(topology_.edges.size()), rings = int(topology_.rings.size());
  const int patches = topology_.patch_count;
  for (int l = from_level; l > to_level; --l) {
    const LevelLayout s = layout(l), d = layout(l - 1);
    const cl::Memory &in = levels_[l - 1].mem(), &out = levels_[l - 2].mem();
    if (d.n > 1) {
      const auto inside = range_interiors(d, d.patches);
      launch(q, k.reduce_interior, inside.first, inside.second, in, out, grid(s), grid(d), patches);
      launch(q, k.reduce_edges, range_edges(d.n - 1, edges), kLocalEdges, in, out, k.edges, edges, grid(s),
             grid(d));
    }
    launch(q, k.reduce_corners, range1d(rings), kLocal1D, in, out, k.rings, k.slots, rings, grid(s),
           grid(d));
  }
}

void Atlas::compute_limit()
{
  if (!limit_positions_) {
    limit_positions_ = std::make_unique<Layer>(make_layer(layout(max_level_)));
    limit_normals_ = std::make_unique<Layer>(make_layer(layout(max_level_)));
    limit_bounds_ = cl::Buffer(runtime_->context(), CL_MEM_READ_WRITE, sizeof(cl_float4) * topology_.patch_count);
  }
  compute_limit_of(max_level_, limit_positions_->mem(), limit_normals_->mem(), nullptr, &limit_bounds_);
  limit_current_ = true;
}

void Atlas::compute_limit_of(int level, const cl::Memory& pos, const cl::Memory& nrm, const PatchSet* set,
                             const cl::Buffer* bounds)
{
  limit_on(level, pos, nrm, device_set(set), bounds);
}

void Atlas::limit_on(int level, const cl::Memory& pos, const cl::Memory& nrm, const DeviceSet& set,
                     const cl::Buffer* bounds)
{
  check_current(set);
  const LevelLayout l = layout(level);
  Kernels& k = *kernels_;
  cl::CommandQueue& q = runtime_->queue();
  const int patches = set.patch_count, edges = set.edge_count, rings = set.ring_count;
  const cl_int generation = set.generation;
  const cl::Memory& in = levels_[level - 1].mem();
  if (l.n > 1 && edges > 0)
    launch(q, k.limit_edges, range1d(edges), kLocal1D, in, k.side_work, k.edges, set.edges, edges,
           set.edge_flags, generation, grid(l));
  if (rings > 0)
    launch(q, k.limit_corners, range1d(rings), kLocal1D, in, k.corner_work, k.rings, k.slots, k.valences,
           set.rings, rings, set.ring_flags, generation, grid(l));
  if (patches > 0) {
    const TileLaunch t = tile_launch(k.limit_tiles, k.limit_patches, l, patches);
    // The per-patch kernel makes the bounds as it goes where it may read
    // back what it wrote (buffers); otherwise a kernel of their own.
    const bool fused = bounds && patch_items_ && storage_ == AtlasStorage::Buffer;
    if (patch_items_)
      k.limit_patches.setArg(12, fused ? *bounds : cl::Buffer()); // its last, beyond limit_tiles' own
    launch(q, t.kernel, t.global, t.local, in, pos, nrm, grid(l), set.patches, patches, set.patch_flags,
           generation, k.patch_sides, k.patch_rings, k.side_work, k.corner_work);
    if (bounds && !fused)
      launch(q, k.patch_bounds, range1d(patches), kLocal1D, pos, grid(l), set.patches, patches,
             set.patch_flags, generation, *bounds);
  }
}

PatchSet Atlas::patch_set(const std::vector<int>& patches, Reach reach) const
{
  patch_marks_.begin(std::size_t(topology_.patch_count));
  std::vector<int> listed;
  listed.reserve(patches.size());
  for (const int p : patches)
    if (patch_marks_.mark(std::size_t(p)))
      listed.push_back(p);
  return marked_set(marked_in_order(std::move(listed), patch_marks_, std::size_t(topology_.patch_count)), reach);
}

std::uint8_t Atlas::outside_bits(int p) const
{
  std::uint8_t corners = 0;
  for (int c = 0; c < 4; ++c)
    if (ring_outside(topology_.patch_corners[std::size_t(p)][std::size_t(c)]))
      corners |= std::uint8_t(1u << c);
  // Side s runs from corner s to corner s + 1, and the patch across it is
  // in both corners' rings (one fan each): only where both rings reach
  // outside can it be outside, so most patches look up no side at all.
  std::uint8_t bits = std::uint8_t(corners << 4);
  for (int s = 0; s < 4; ++s)
    if ((corners >> s & 1) && (corners >> ((s + 1) & 3) & 1)) {
      const int q = topology_.across(p, s);
      if (q >= 0 && !patch_marks_.marked(std::size_t(q)))
        bits |= std::uint8_t(1u << s);
    }
  return bits;
}

bool Atlas::ring_outside(int v) const
{
  // About four patches meet at a corner: each ring is scanned once.
  if (ring_known_.mark(std::size_t(v))) {
    const CornerRing& ring = topology_.rings[std::size_t(v)];
    bool outside = false;
    for (int m = 0; m < ring.count && !outside; ++m)
      outside = !patch_marks_.marked(std::size_t(topology_.slots[std::size_t(ring.first + m)].patch));
    ring_outside_[std::size_t(v)] = outside;
  }
  return ring_outside_[std::size_t(v)];
}

void Atlas::begin_outside() const
{
  ring_known_.begin(topology_.rings.size());
  ring_outside_.resize(topology_.rings.size());
}

PatchSet Atlas::marked_set(std::vector<int> patches, Reach reach) const
{
  PatchSet set;
  set.patches = std::move(patches);
  edge_marks_.begin(topology_.edges.size());
  ring_marks_.begin(topology_.rings.size());
  if (reach == Reach::All) {
    set.outside.reserve(set.patches.size());
    begin_outside();
  }
  for (const int p : set.patches) {
    // By Reach::All, a side or corner shared with a patch outside stays out.
    const std::uint8_t outside = reach == Reach::All ? outside_bits(p) : 0;
    if (reach == Reach::All)
      set.outside.push_back(outside);
    for (int s = 0; s < 4; ++s) {
      const int e = topology_.patch_sides[std::size_t(p)][std::size_t(s)];
      if (edge_marks_.mark(std::size_t(e)) && !(outside >> s & 1))
        set.edges.push_back(e);
      const int v = topology_.patch_corners[std::size_t(p)][std::size_t(s)];
      if (ring_marks_.mark(std::size_t(v)) && !(outside >> (4 + s) & 1)) {
        set.rings.push_back(device_ring_[std::size_t(v)]);
        set.corners.push_back(v);
      }
    }
  }
  return set;
}

std::vector<std::uint8_t> Atlas::shared_outside(const std::vector<int>& patches) const
{
  patch_marks_.begin(std::size_t(topology_.patch_count));
  for (const int p : patches)
    patch_marks_.mark(std::size_t(p));
  begin_outside();
  std::vector<std::uint8_t> out(patches.size());
  for (std::size_t k = 0; k < patches.size(); ++k)
    out[k] = outside_bits(patches[k]);
  return out;
}

PatchSet Atlas::neighbourhood_set(const std::vector<int>& changed) const
{
  // The rings at the changed patches' corners hold the neighbourhood; the
  // set's edges and rings are then every side and corner of it.
  patch_marks_.begin(std::size_t(topology_.patch_count));
  ring_seen_.begin(topology_.rings.size());
  std::vector<int> around;
  around.reserve(2 * changed.size());
  for (const int p : changed)
    for (int c = 0; c < 4; ++c) {
      const int v = topology_.patch_corners[std::size_t(p)][std::size_t(c)];
      if (!ring_seen_.mark(std::size_t(v)))
        continue;
      const CornerRing& ring = topology_.rings[std::size_t(v)];
      for (int m = 0; m < ring.count; ++m) {
        const int q = topology_.slots[std::size_t(ring.first + m)].patch;
        if (patch_marks_.mark(std::size_t(q)))
          around.push_back(q);
      }
    }
  return marked_set(marked_in_order(std::move(around), patch_marks_, std::size_t(topology_.patch_count)), Reach::Any);
}

DeviceSet Atlas::device_set(const PatchSet* set) const
{
  DeviceSet lists;
  if (!set) {
    lists.patch_count = topology_.patch_count;
    lists.edge_count = int(topology_.edges.size());
    lists.ring_count = int(topology_.rings.size());
    return lists;
  }
  const cl::Context& context = runtime_->context();
  lists.patches = device_ints(context, set->patches);
  lists.edges = device_ints(context, set->edges);
  lists.rings = device_ints(context, set->rings);
  lists.patch_count = int(set->patches.size());
  lists.edge_count = int(set->edges.size());
  lists.ring_count = int(set->rings.size());
  return lists;
}

void Atlas::check_current(const DeviceSet& set) const
{
  // Flags of an older set have been overwritten where the sets differ.
  if (set.patch_flags() && set.generation != kernels_->generation)
    throw std::logic_error("a device-made set used after a newer one was made");
}

DeviceSet Atlas::neighbourhood_on_device(const std::vector<int>& changed, const cl::Buffer* list)
{
  if (changed.size() == std::size_t(topology_.patch_count))
    return device_set(nullptr); // every patch: no set to make
  // Host lists cost per patch listed, on one core; the flags' passes cost
  // per item of the atlas, on every core. Sculpt steps on armadillo L2
  // broke even at 4-5% of the patches (host lists faster at 3.5%, flags at
  // 5.4% and more): flags from a sixteenth on (kDeviceSetShare).
  if (changed.size() * device_set_share_ < std::size_t(topology_.patch_count)) {
    const PatchSet set = neighbourhood_set(changed);
    return device_set(&set);
  }
  Kernels& k = *kernels_;
  cl::CommandQueue& q = runtime_->queue();
  if (++k.generation == 0) { // a flag may still hold any other generation
    for (const cl::Buffer* b : {&k.patch_flags, &k.edge_flags, &k.ring_flags})
      q.enqueueFillBuffer(*b, cl_uint(0), 0, b->getInfo<CL_MEM_SIZE>());
    k.generation = 1;
  }
  const cl_int generation = k.generation, count = cl_int(changed.size()), patches = topology_.patch_count,
               rings = cl_int(topology_.rings.size());
  const cl::Buffer uploaded = list ? cl::Buffer() : device_ints(runtime_->context(), changed);
  // The changed patches' corners, the patches there, and their sides and
  // corners: a subset of the last, so the ring flags serve both.
  launch(q, k.flag_corners, range1d(count), kLocal1D, list ? *list : uploaded, count, k.patch_rings, generation,
         k.ring_flags);
  launch(q, k.flag_ring_patches, range1d(rings), kLocal1D, k.ring_flags, rings, k.rings, k.slots, generation,
         k.patch_flags);
  launch(q, k.flag_borders, range1d(patches), kLocal1D, k.patch_flags, patches, k.patch_sides, k.patch_rings,
         generation, k.edge_flags, k.ring_flags);
  DeviceSet flagged = device_set(nullptr);
  flagged.patch_flags = k.patch_flags;
  flagged.edge_flags = k.edge_flags;
  flagged.ring_flags = k.ring_flags;
  flagged.generation = generation;
  return flagged;
}

void Atlas::update_limit(const PatchSet& set)
{
  // A stale limit (limit_current_ is never set without the layers) or a
  // set of everything: the whole limit, with no lists to build or upload.
  if (!limit_current_ || int(set.patches.size()) == topology_.patch_count)
    compute_limit();
  else
    update_limit(device_set(&set));
}

void Atlas::update_limit(const DeviceSet& set)
{
  if (!limit_current_)
    compute_limit();
  else
    limit_on(max_level_, limit_positions_->mem(), limit_normals_->mem(), set, &limit_bounds_);
}

const cl::Memory& Atlas::level_layer(int level)
{
  if (level < 1 || level > max_level_)
    throw InputError("no level " + std::to_string(level) + " in this atlas");
  return levels_[level - 1].mem();
}

const cl::Memory& Atlas::limit_normals_layer()
{
  if (!limit_current_)
    compute_limit();
  return limit_normals_->mem();
}

const cl::Buffer& Atlas::edge_table() const { return kernels_->edges; }
Atlas::BorderWork Atlas::border_work() const
{
  return {kernels_->patch_sides, kernels_->patch_rings, kernels_->side_work, kernels_->corner_work};
}
const cl::Buffer& Atlas::ring_table() const { return kernels_->rings; }
const cl::Buffer& Atlas::slot_table() const { return kernels_->slots; }

void Atlas::finish() { runtime_->queue().finish(); }

void Atlas::assume_limit_current() { limit_current_ = limit_positions_ != nullptr; }

std::vector<Float4> Atlas::read_layer(const Layer& layer, const LevelLayout& l)
{
  std::vector<Float4> out(l.texels());
  if (storage_ == AtlasStorage::Image) {
    std::vector<Float4> image(l.image_texels());
    runtime_->queue().enqueueReadImage(layer.image, CL_TRUE, {0, 0, 0},
                                       {std::size_t(l.width), std::size_t(l.height), 1}, 0, 0, image.data());
    for_each_tile_row(l, [&](std::size_t at, std::size_t in_image) {
      std::copy_n(&image[in_image], l.tile, &out[at]);
    });
  } else {
    runtime_->queue().enqueueReadBuffer(layer.buffer, CL_TRUE, 0, layer_bytes(l, storage_), out.data());
  }
  return out;
}

void Atlas::write_layer(Layer& layer, const LevelLayout& l, const std::vector<Float4>& texels)
{
  if (texels.size() != l.texels())
    throw InputError("level " + std::to_string(l.level) + " holds " + std::to_string(l.texels()) +
                     " texels, not " + std::to_string(texels.size()));
  if (storage_ == AtlasStorage::Image) {
    std::vector<Float4> image(l.image_texels(), Float4{0.f, 0.f, 0.f, 0.f});
    for_each_tile_row(l, [&](std::size_t at, std::size_t in_image) {
      std::copy_n(&texels[at], l.tile, &image[in_image]);
    });
    runtime_->queue().enqueueWriteImage(layer.image, CL_TRUE, {0, 0, 0},
                                        {std::size_t(l.width), std::size_t(l.height), 1}, 0, 0, image.data());
  } else {
    runtime_->queue().enqueueWriteBuffer(layer.buffer, CL_TRUE, 0, layer_bytes(l, storage_), texels.data());
  }
}

std::vector<Float4> Atlas::read_positions(int level)
{
  if (level < 1 || level > max_level_)
    throw InputError("no level " + std::to_string(level) + " in this atlas (1.." +
                     std::to_string(max_level_) + ")");
  return read_layer(levels_[level - 1], layout(level));
}

void Atlas::write_positions(int level, const std::vector<Float4>& texels)
{
  if (level < 1 || level > max_level_)
    throw InputError("no level " + std::to_string(level) + " in this atlas (1.." +
                     std::to_string(max_level_) + ")");
  write_layer(levels_[level - 1], layout(level), texels);
  if (level == max_level_)
    limit_current_ = false;
}

const cl::Memory& Atlas::limit_positions_layer()
{
  if (!limit_current_)
    compute_limit();
  return limit_positions_->mem();
}

const cl::Buffer& Atlas::limit_bounds()
{
  if (!limit_current_)
    compute_limit();
  return limit_bounds_;
}

std::vector<Float4> Atlas::read_limit_positions()
{
  if (!limit_current_)
    compute_limit();
  return read_layer(*limit_positions_, layout(max_level_));
}

std::vector<Float4> Atlas::read_limit_normals()
{
  if (!limit_current_)
    compute_limit();
  return read_layer(*limit_normals_, layout(max_level_));
}

} // namespace meshpaint
