#include "atlas/atlas.h"

#include "cl/program.h"
#include "core/errors.h"
#include "core/format.h"
#include "mesh/far_refiner.h"

#include <algorithm> // for std::max
#include <cstdlib>   // for std::getenv

namespace meshpaint {
namespace {

// Work-group shapes: rows of texels for the atlas-wide kernels, runs of
// edges or rings for the table-driven ones.
constexpr std::size_t kGroupX = 32, kGroupY = 4, kGroup1D = 64;
const cl::NDRange kLocal2D(kGroupX, kGroupY), kLocalEdges(1, kGroup1D), kLocal1D(kGroup1D);

std::size_t round_up(std::size_t x, std::size_t m) { return (x + m - 1) / m * m; }

cl::NDRange range2d(const LevelLayout& l)
{
  return cl::NDRange(round_up(l.width, kGroupX), round_up(l.height, kGroupY));
}
cl::NDRange range_edges(int positions, int edges)
{
  return cl::NDRange(positions, round_up(edges, kGroup1D));
}
cl::NDRange range1d(int items) { return cl::NDRange(round_up(items, kGroup1D)); }

//! Sets the kernel's arguments in order and enqueues it.
template <typename... Args>
void launch(cl::CommandQueue& q, cl::Kernel& kernel, const cl::NDRange& global, const cl::NDRange& local,
            const Args&... args)
{
  cl_uint index = 0;
  (kernel.setArg(index++, args), ...);
  q.enqueueNDRangeKernel(kernel, cl::NullRange, global, local);
}

} // namespace

AtlasStorage parse_storage(const std::string& name)
{
  if (name == "buffer")
    return AtlasStorage::Buffer;
  if (name == "image")
    return AtlasStorage::Image;
  throw InputError("unknown atlas storage '" + name + "' (buffer or image)");
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

MemoryPlan plan_memory(const AtlasTopology& topology, int level)
{
  MemoryPlan plan;
  for (int l = 1; l <= level; ++l)
    plan.total += level_layout(topology.patch_count, l).layer_bytes();
  plan.finest = level_layout(topology.patch_count, level);
  plan.largest_allocation = plan.finest.layer_bytes();
  plan.total += 2 * plan.largest_allocation; // limit positions and normals
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
  cl::Kernel subdivide_interior, subdivide_edges, subdivide_corners;
  cl::Kernel limit_interior, limit_edges, limit_corners;
  cl::Kernel reduce_interior, reduce_edges, reduce_corners;
  cl::Buffer edges, rings, slots;
};

namespace {

//! Why `level` does not fit `device`, or an empty string when it does.
std::string misfit(const AtlasTopology& topo, int level, const DeviceInfo& device, AtlasStorage storage)
{
  const MemoryPlan plan = plan_memory(topo, level);
  const LevelLayout& l = plan.finest;
  if (storage == AtlasStorage::Image &&
      (std::size_t(l.width) > device.image_max_width || std::size_t(l.height) > device.image_max_height))
    return "an atlas of " + std::to_string(l.width) + "x" + std::to_string(l.height) +
           " texels, larger than the device's largest image (" +
           std::to_string(device.image_max_width) + "x" + std::to_string(device.image_max_height) + ")";
  if (l.texels() >= (std::size_t(1) << 31))
    return std::to_string(l.texels()) + " texels, more than 2^31 (32-bit texel indices)";
  if (plan.largest_allocation > device.max_allocation)
    return format_bytes(plan.largest_allocation) + " in one layer, more than the device's largest "
           "allocation (" + format_bytes(device.max_allocation) + ")";
  if (plan.total > device.global_memory)
    return format_bytes(plan.total) + " in all, more than the device's memory (" +
           format_bytes(device.global_memory) + ")";
  return "";
}

} // namespace

Atlas::Atlas(std::shared_ptr<Runtime> runtime, const BaseMesh& mesh, int max_level,
             AtlasStorage storage)
  : runtime_(std::move(runtime)), storage_(storage), max_level_(max_level)
{
  if (max_level < 1 || max_level > kMaxLevel)
    throw InputError("level " + std::to_string(max_level) + " is out of range (1.." +
                     std::to_string(kMaxLevel) + ")");
  const DeviceInfo& device = runtime_->info();
  if (storage_ == AtlasStorage::Image && !device.images)
    throw DeviceError(device.name + " has no image support; use --storage buffer");

  auto refiner = make_refiner(mesh);
  refine_uniform(*refiner, 1, true); // full topology: edges and vertex rings
  topology_ = build_atlas_topology(refiner->GetLevel(1));

  if (const std::string why = misfit(topology_, max_level, device, storage_); !why.empty()) {
    int fits = 0;
    for (int l = 1; l < max_level && misfit(topology_, l, device, storage_).empty(); ++l)
      fits = l;
    throw ResourceError("level " + std::to_string(max_level) + " of '" + mesh.name + "' needs " +
                        why + "; " +
                        (fits ? "the largest level that fits is " + std::to_string(fits)
                              : std::string("not even level 1 fits")));
  }

  // Level 1: the first Catmull-Clark step, one 2x2 tile per quad.
  const std::vector<Vec3> level1 = interpolate_levels(*refiner, mesh.points)[1];
  const LevelLayout l1 = layout(1);
  std::vector<Float4> texels(l1.texels(), Float4{0.f, 0.f, 0.f, 0.f});
  static const int corner_xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int p = 0; p < topology_.patch_count; ++p) {
    const int ox = (p % l1.tiles_x) * l1.tile, oy = (p / l1.tiles_x) * l1.tile;
    for (int c = 0; c < 4; ++c) {
      const Vec3& v = level1[topology_.patch_corners[p][c]];
      texels[std::size_t(oy + corner_xy[c][1]) * l1.width + ox + corner_xy[c][0]] = {v[0], v[1], v[2], 0.f};
    }
  }

  try {
    for (int l = 1; l <= max_level_; ++l)
      levels_.push_back(make_layer(layout(l), l == 1, l == 1 ? texels.data() : nullptr));

    kernels_ = std::make_unique<Kernels>();
    Kernels& k = *kernels_;
    const std::string options =
      std::string("-cl-std=CL1.2") + (storage_ == AtlasStorage::Image ? " -D ATLAS_IMAGE" : "");
    k.program = build_program(*runtime_,
                              {"atlas_types.h", "atlas_access.cl", "subdivide.cl", "limit.cl", "reduce.cl"},
                              options);
    k.subdivide_interior = cl::Kernel(k.program, "subdivide_interior");
    k.subdivide_edges = cl::Kernel(k.program, "subdivide_edges");
    k.subdivide_corners = cl::Kernel(k.program, "subdivide_corners");
    k.limit_interior = cl::Kernel(k.program, "limit_interior");
    k.limit_edges = cl::Kernel(k.program, "limit_edges");
    k.limit_corners = cl::Kernel(k.program, "limit_corners");
    k.reduce_interior = cl::Kernel(k.program, "reduce_interior");
    k.reduce_edges = cl::Kernel(k.program, "reduce_edges");
    k.reduce_corners = cl::Kernel(k.program, "reduce_corners");
    const auto upload = [&](const auto& v) {
      return cl::Buffer(runtime_->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                        std::max<std::size_t>(1, v.size() * sizeof(v[0])),
                        const_cast<void*>(static_cast<const void*>(v.data())));
    };
    k.edges = upload(topology_.edges);
    k.rings = upload(topology_.rings);
    k.slots = upload(topology_.slots);
  } catch (const cl::Error& e) {
    throw DeviceError("cannot set up the atlas on " + device.name + ": " + describe(e));
  }
}

Atlas::~Atlas() = default;

LevelLayout Atlas::layout(int level) const { return level_layout(topology_.patch_count, level); }

Atlas::Layer Atlas::make_layer(const LevelLayout& l, bool filled_from_host, const void* data)
{
  Layer layer;
  const cl_mem_flags flags = CL_MEM_READ_WRITE | (filled_from_host ? CL_MEM_COPY_HOST_PTR : 0);
  void* host = const_cast<void*>(data);
  if (storage_ == AtlasStorage::Image) {
    layer.image = cl::Image2D(runtime_->context(), flags, cl::ImageFormat(CL_RGBA, CL_FLOAT),
                              l.width, l.height, 0, host);
    if (!filled_from_host)
      runtime_->queue().enqueueFillImage(layer.image, cl_float4{{0.f, 0.f, 0.f, 0.f}}, {0, 0, 0},
                                         {std::size_t(l.width), std::size_t(l.height), 1});
  } else {
    layer.buffer = cl::Buffer(runtime_->context(), flags, l.layer_bytes(), host);
    if (!filled_from_host)
      runtime_->queue().enqueueFillBuffer(layer.buffer, cl_float4{{0.f, 0.f, 0.f, 0.f}}, 0, l.layer_bytes());
  }
  return layer;
}

void Atlas::subdivide(int from_level, int to_level)
{
  if (from_level < 1 || to_level > max_level_ || from_level > to_level)
    throw InputError("cannot subdivide from level " + std::to_string(from_level) + " to " +
                     std::to_string(to_level) + " (atlas levels 1.." + std::to_string(max_level_) + ")");
  Kernels& k = *kernels_;
  cl::CommandQueue& q = runtime_->queue();
  const int edges = int(topology_.edges.size()), rings = int(topology_.rings.size());
  const int patches = topology_.patch_count;
  for (int l = from_level; l < to_level; ++l) {
    const LevelLayout s = layout(l), d = layout(l + 1);
    const cl::Memory &in = levels_[l - 1].mem(), &out = levels_[l].mem();
    launch(q, k.subdivide_interior, range2d(d), kLocal2D, in, out, s.n, s.tiles_x, patches, s.width, d.width);
    launch(q, k.subdivide_edges, range_edges(2 * s.n - 1, edges), kLocalEdges, in, out, k.edges, edges,
           s.n, s.tiles_x, s.width, d.width);
    launch(q, k.subdivide_corners, range1d(rings), kLocal1D, in, out, k.rings, k.slots, rings, s.n,
           s.tiles_x, s.width, d.width);
  }
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
    launch(q, k.reduce_interior, range2d(d), kLocal2D, in, out, d.n, d.tiles_x, patches, s.width, d.width);
    if (d.n > 1)
      launch(q, k.reduce_edges, range_edges(d.n - 1, edges), kLocalEdges, in, out, k.edges, edges, d.n,
             d.tiles_x, s.width, d.width);
    launch(q, k.reduce_corners, range1d(rings), kLocal1D, in, out, k.rings, k.slots, rings, d.n,
           d.tiles_x, s.width, d.width);
  }
}

void Atlas::compute_limit()
{
  const LevelLayout l = layout(max_level_);
  if (!limit_positions_) {
    limit_positions_ = std::make_unique<Layer>(make_layer(l, false, nullptr));
    limit_normals_ = std::make_unique<Layer>(make_layer(l, false, nullptr));
  }
  Kernels& k = *kernels_;
  cl::CommandQueue& q = runtime_->queue();
  const int edges = int(topology_.edges.size()), rings = int(topology_.rings.size());
  const cl::Memory &in = levels_[max_level_ - 1].mem(), &pos = limit_positions_->mem(),
                   &nrm = limit_normals_->mem();
  launch(q, k.limit_interior, range2d(l), kLocal2D, in, pos, nrm, l.n, l.tiles_x, topology_.patch_count,
         l.width);
  if (l.n > 1)
    launch(q, k.limit_edges, range_edges(l.n - 1, edges), kLocalEdges, in, pos, nrm, k.edges, edges, l.n,
           l.tiles_x, l.width);
  launch(q, k.limit_corners, range1d(rings), kLocal1D, in, pos, nrm, k.rings, k.slots, rings, l.n,
         l.tiles_x, l.width);
}

void Atlas::finish() { runtime_->queue().finish(); }

std::vector<Float4> Atlas::read_layer(const Layer& layer, const LevelLayout& l)
{
  std::vector<Float4> out(l.texels());
  if (storage_ == AtlasStorage::Image)
    runtime_->queue().enqueueReadImage(layer.image, CL_TRUE, {0, 0, 0},
                                       {std::size_t(l.width), std::size_t(l.height), 1}, 0, 0, out.data());
  else
    runtime_->queue().enqueueReadBuffer(layer.buffer, CL_TRUE, 0, l.layer_bytes(), out.data());
  return out;
}

void Atlas::write_layer(Layer& layer, const LevelLayout& l, const std::vector<Float4>& texels)
{
  if (texels.size() != l.texels())
    throw InputError("level " + std::to_string(l.level) + " holds " + std::to_string(l.texels()) +
                     " texels, not " + std::to_string(texels.size()));
  if (storage_ == AtlasStorage::Image)
    runtime_->queue().enqueueWriteImage(layer.image, CL_TRUE, {0, 0, 0},
                                        {std::size_t(l.width), std::size_t(l.height), 1}, 0, 0, texels.data());
  else
    runtime_->queue().enqueueWriteBuffer(layer.buffer, CL_TRUE, 0, l.layer_bytes(), texels.data());
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
}

std::vector<Float4> Atlas::read_limit_positions()
{
  if (!limit_positions_)
    compute_limit();
  return read_layer(*limit_positions_, layout(max_level_));
}

std::vector<Float4> Atlas::read_limit_normals()
{
  if (!limit_normals_)
    compute_limit();
  return read_layer(*limit_normals_, layout(max_level_));
}

} // namespace meshpaint
