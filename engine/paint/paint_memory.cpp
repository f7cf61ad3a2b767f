#include "paint/paint_memory.h"

#include "atlas/atlas.h"
#include "atlas/multires.h"
#include "cl/runtime.h"
#include "core/errors.h"
#include "core/format.h"
#include "paint/welded_smoothing.h"

namespace meshpaint {
namespace {

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
  const std::size_t total = painting_bytes(topology, level, storage);
  if (total > device.global_memory)
    return format_bytes(total) + " with its paint layers, more than " + device.memory_name() + " (" +
           format_bytes(device.global_memory) + ")";
  return "";
}

} // namespace

std::size_t painting_bytes(const AtlasTopology& topology, int level, AtlasStorage storage)
{
  const MemoryPlan plan = plan_memory(topology, level, storage);
  return plan.total + paint_bytes(plan.finest, storage) +
         WeldedSmoothing::bytes(plan.finest.texels(), topology.unique_vertices(level));
}

std::size_t coarse_edits_bytes(const AtlasTopology& topology, int level, AtlasStorage storage, const DeviceInfo& device)
{
  return painting_bytes(topology, level, storage) +
         Multires::device_bytes(topology.patch_count, level, storage, AtlasEvaluator::patch_items_on(device));
}

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

void check_coarse_edits_fit(const Atlas& atlas)
{
  const DeviceInfo& device = atlas.shared_runtime()->info();
  const int level = atlas.max_level();
  const std::size_t total = painting_bytes(atlas.topology(), level, atlas.storage()) + Multires::device_bytes(atlas);
  if (total <= device.global_memory)
    return;
  throw ResourceError("editing below painting level " + std::to_string(level) + " needs " + format_bytes(total) +
                      " with the multiresolution layers, more than " + device.memory_name() + " (" +
                      format_bytes(device.global_memory) + "); edit at the painting level, or paint at a lower one");
}

} // namespace meshpaint
