// Device memory an atlas needs, worked out before anything is allocated, and
// whether a level fits a device.
#pragma once

#include "atlas/atlas_storage.h"
#include "atlas/atlas_topology.h"
#include "atlas/patch_layout.h"
#include "cl/runtime.h"

#include <cstddef> // for std::size_t
#include <string>  // for std::string

namespace meshpaint {

//! Bytes of one float4 layer of a level in the given storage.
std::size_t layer_bytes(const LevelLayout& layout, AtlasStorage storage);

//! float4 per ring of the corner results an atlas subdivided up to
//! `finest_level` keeps: position and normal of the limit, or the corners of
//! every step from level 1, which CPUs compute in one pass.
std::size_t corner_work_layers(int finest_level);

//! Device memory an atlas up to `level` needs, checked before allocating.
struct MemoryPlan
{
  LevelLayout finest;
  std::size_t largest_allocation = 0; //!< bytes, one layer of the finest level
  std::size_t total = 0;              //!< bytes, all levels plus limit layers
};
MemoryPlan plan_memory(const AtlasTopology& topology, int level, AtlasStorage storage);

//! Why an atlas up to `level` does not fit the device (image size, largest
//! allocation, total memory, 32-bit texel indices), or "" when it fits.
std::string fit_problem(const AtlasTopology& topology, int level, const DeviceInfo& device,
                        AtlasStorage storage);
//! Highest level that fits, 0 when none does.
int largest_fitting_level(const AtlasTopology& topology, const DeviceInfo& device, AtlasStorage storage);

} // namespace meshpaint
