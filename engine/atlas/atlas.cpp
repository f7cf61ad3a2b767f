#include "atlas/atlas.h"

#include "cl/launch.h"
#include "core/errors.h"
#include "mesh/far_refiner.h"
#include "mesh/spatial_order.h"

namespace meshpaint {

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
  AtlasTopology topology = build_atlas_topology(refiner->GetLevel(1));

  if (const std::string why = fit_problem(topology, max_level, device, storage_); !why.empty()) {
    const int fits = largest_fitting_level(topology, device, storage_);
    throw ResourceError("level " + std::to_string(max_level) + " of '" + mesh.name + "' needs " +
                        why + "; " +
                        (fits ? "the largest level that fits is " + std::to_string(fits)
                              : std::string("not even level 1 fits")));
  }

  // Level 1: the first Catmull-Clark step, one 2x2 tile per quad.
  const std::vector<Vec3> level1 = interpolate_levels(*refiner, base_.points)[1];
  const LevelLayout l1 = level_layout(topology.patch_count, 1);
  std::vector<Float4> texels(l1.texels(), Float4{0.f, 0.f, 0.f, 0.f});
  static const int corner_xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int p = 0; p < topology.patch_count; ++p)
    for (int c = 0; c < 4; ++c) {
      const Vec3& v = level1[topology.patch_corners[p][c]];
      texels[l1.index(p, corner_xy[c][0], corner_xy[c][1])] = {v[0], v[1], v[2], 0.f};
    }

  try {
    for (int l = 1; l <= max_level_; ++l)
      levels_.push_back(allocate_layer(*runtime_, level_layout(topology.patch_count, l), storage_));
    write_layer(*runtime_, levels_[0], l1, storage_, texels);
    tables_ = std::make_unique<AtlasTables>(*runtime_, std::move(topology));
    evaluator_ = std::make_unique<AtlasEvaluator>(*runtime_, *tables_, storage_, layout(max_level_));
    sets_ = std::make_unique<PatchSetMaker>(*tables_);
  } catch (const cl::Error& e) {
    throw DeviceError("cannot set up the atlas on " + device.name + ": " + describe(e));
  }
}

Atlas::~Atlas() = default;

LevelLayout Atlas::layout(int level) const { return level_layout(topology().patch_count, level); }

void Atlas::subdivide(int from_level, int to_level) { subdivide(from_level, to_level, PatchSet()); }

void Atlas::subdivide(int from_level, int to_level, const PatchSet& set, const cl::Memory* last)
{
  if (from_level < 1 || to_level > max_level_ || from_level > to_level)
    throw InputError("cannot subdivide from level " + std::to_string(from_level) + " to " +
                     std::to_string(to_level) + " (atlas levels 1.." + std::to_string(max_level_) + ")");
  std::vector<cl::Memory> layers(levels_.begin() + (from_level - 1), levels_.begin() + to_level);
  if (last && from_level < to_level)
    layers.back() = *last;
  else if (to_level == max_level_ && from_level < to_level)
    limit_current_ = false;
  evaluator_->subdivide(from_level, layers, set);
}

int Atlas::subdivide_but_last_tiles(int from_level, const PatchSet& set)
{
  if (from_level < 1 || from_level >= max_level_)
    throw InputError("cannot subdivide from level " + std::to_string(from_level) + " to " +
                     std::to_string(max_level_) + " (atlas levels 1.." + std::to_string(max_level_) + ")");
  const std::vector<cl::Memory> layers(levels_.begin() + (from_level - 1), levels_.end());
  return evaluator_->subdivide(from_level, layers, set, false);
}

void Atlas::reduce(int from_level, int to_level)
{
  if (to_level < 1 || from_level > max_level_ || to_level > from_level)
    throw InputError("cannot reduce from level " + std::to_string(from_level) + " to " +
                     std::to_string(to_level) + " (atlas levels 1.." + std::to_string(max_level_) + ")");
  evaluator_->reduce(from_level, to_level, levels_);
}

void Atlas::compute_limit()
{
  if (!limit_positions_()) {
    limit_positions_ = allocate_layer(*runtime_, layout(max_level_), storage_);
    limit_normals_ = allocate_layer(*runtime_, layout(max_level_), storage_);
    limit_bounds_ = cl::Buffer(runtime_->context(), CL_MEM_READ_WRITE, sizeof(cl_float4) * topology().patch_count);
    limit_clusters_ = cl::Buffer(runtime_->context(), CL_MEM_READ_WRITE,
                                 sizeof(cl_float4) * std::size_t(cluster_count(topology().patch_count)));
  }
  compute_limit_of(max_level_, limit_positions_, limit_normals_, PatchSet(), &limit_bounds_);
  evaluator_->cluster_bounds(limit_bounds_, limit_clusters_, PatchSet());
  limit_current_ = true;
}

void Atlas::compute_limit_of(int level, const cl::Memory& pos, const cl::Memory& nrm, const PatchSet& set,
                             const cl::Buffer* bounds)
{
  evaluator_->limit(level, levels_[level - 1], pos, nrm, set, bounds);
}

PatchSet Atlas::patch_set(const std::vector<int>& patches, Reach reach) const
{
  return sets_->lists(patches, reach);
}

std::vector<std::uint8_t> Atlas::shared_outside(const std::vector<int>& patches) const
{
  return sets_->shared_outside(patches);
}

std::vector<int> Atlas::corner_neighbourhood(const std::vector<int>& patches) const
{
  return sets_->corner_neighbourhood(patches);
}

PatchSet Atlas::neighbourhood(const std::vector<int>& changed, const cl::Buffer* list)
{
  if (changed.size() == std::size_t(topology().patch_count))
    return PatchSet(); // every patch: no set to make
  // Host lists cost per patch listed, on one core; the flags' passes cost
  // per item of the atlas, on every core: flags pay from about a sixteenth
  // of the patches on (kDeviceSetShare).
  if (sets_on_device(changed.size()))
    return evaluator_->flag_neighbourhood(changed, list);
  PatchSet set = sets_->neighbourhood(changed);
  const cl::Context& context = runtime_->context();
  set.patch_list = device_ints(context, set.patches);
  set.edge_list = device_ints(context, set.edges);
  set.ring_list = device_ints(context, set.rings);
  return set;
}

void Atlas::update_limit(const PatchSet& set)
{
  // A stale limit (limit_current_ is never set without the layers) or a
  // set of everything: the whole limit, with no lists to build or upload.
  const bool everything = set.form == PatchSet::Form::All ||
                          (set.form == PatchSet::Form::Lists && int(set.patches.size()) == topology().patch_count);
  if (!limit_current_ || everything)
    compute_limit();
  else {
    evaluator_->limit(max_level_, levels_.back(), limit_positions_, limit_normals_, set, &limit_bounds_);
    evaluator_->cluster_bounds(limit_bounds_, limit_clusters_, set);
  }
}

const cl::Memory& Atlas::level_layer(int level)
{
  if (level < 1 || level > max_level_)
    throw InputError("no level " + std::to_string(level) + " in this atlas");
  return levels_[level - 1];
}

const cl::Memory& Atlas::limit_normals_layer()
{
  if (!limit_current_)
    compute_limit();
  return limit_normals_;
}

void Atlas::finish() { runtime_->queue().finish(); }

void Atlas::assume_limit_current() { limit_current_ = limit_positions_() != nullptr; }

std::vector<Float4> Atlas::read_positions(int level)
{
  if (level < 1 || level > max_level_)
    throw InputError("no level " + std::to_string(level) + " in this atlas (1.." +
                     std::to_string(max_level_) + ")");
  return read_layer(*runtime_, levels_[level - 1], layout(level), storage_);
}

void Atlas::write_positions(int level, const std::vector<Float4>& texels)
{
  if (level < 1 || level > max_level_)
    throw InputError("no level " + std::to_string(level) + " in this atlas (1.." +
                     std::to_string(max_level_) + ")");
  write_layer(*runtime_, levels_[level - 1], layout(level), storage_, texels);
  if (level == max_level_)
    limit_current_ = false;
}

const cl::Memory& Atlas::limit_positions_layer()
{
  if (!limit_current_)
    compute_limit();
  return limit_positions_;
}

const cl::Buffer& Atlas::limit_bounds()
{
  if (!limit_current_)
    compute_limit();
  return limit_bounds_;
}

const cl::Buffer& Atlas::limit_cluster_bounds()
{
  if (!limit_current_)
    compute_limit();
  return limit_clusters_;
}

std::vector<Float4> Atlas::read_limit_positions()
{
  if (!limit_current_)
    compute_limit();
  return read_layer(*runtime_, limit_positions_, layout(max_level_), storage_);
}

std::vector<Float4> Atlas::read_limit_normals()
{
  if (!limit_current_)
    compute_limit();
  return read_layer(*runtime_, limit_normals_, layout(max_level_), storage_);
}

} // namespace meshpaint
