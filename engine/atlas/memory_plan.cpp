#include "atlas/memory_plan.h"

#include "cl/opencl.h"
#include "core/format.h"

#include <algorithm> // for std::max

namespace meshpaint {
namespace {

//! Bytes of the whole-tile kernels' tables and the compact results of the
//! side and corner kernels at a level (AtlasTables, AtlasEvaluator).
std::size_t border_work_bytes(const AtlasTopology& topo, const LevelLayout& l)
{
  return std::size_t(topo.patch_count) * 4 * sizeof(cl_int4) + // patch_sides, _rings, _across, _slots
         (topo.edges.size() * std::size_t(l.n - 1) * 2 + topo.rings.size() * corner_work_layers(l.level)) *
             sizeof(cl_float4) +
         topo.rings.size(); // a mark per ring
}

} // namespace

std::size_t corner_work_layers(int finest_level) { return std::size_t(std::max(2, finest_level - 1)); }

std::size_t layer_bytes(const LevelLayout& l, AtlasStorage storage)
{
  return 16 * (storage == AtlasStorage::Image ? l.image_texels() : l.texels());
}

MemoryPlan plan_memory(const AtlasTopology& topology, int level, AtlasStorage storage)
{
  MemoryPlan plan;
  for (int l = 1; l <= level; ++l)
    plan.total += layer_bytes(level_layout(topology.patch_count, l), storage);
  plan.finest = level_layout(topology.patch_count, level);
  plan.largest_allocation = layer_bytes(plan.finest, storage);
  plan.total += 2 * plan.largest_allocation; // limit positions and normals
  plan.total += // their bounds, per patch and per cluster
    std::size_t(topology.patch_count + cluster_count(topology.patch_count)) * sizeof(cl_float4);
  plan.total += border_work_bytes(topology, plan.finest);
  plan.total += topology.edges.size() * sizeof(PatchEdge) +
                topology.rings.size() * sizeof(CornerRing) +
                topology.slots.size() * sizeof(CornerSlot);
  return plan;
}

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
    return format_bytes(plan.largest_allocation) + " in one layer, more than " +
           (device.address_space_limited ? device.memory_name() : "the device's largest allocation") + " (" +
           format_bytes(device.max_allocation) + ")";
  if (plan.total > device.global_memory)
    return format_bytes(plan.total) + " in all, more than " + device.memory_name() + " (" +
           format_bytes(device.global_memory) + ")";
  return "";
}

int largest_fitting_level(const AtlasTopology& topology, const DeviceInfo& device, AtlasStorage storage)
{
  int fits = 0;
  while (fits < kMaxLevel && fit_problem(topology, fits + 1, device, storage).empty())
    ++fits;
  return fits;
}

} // namespace meshpaint
