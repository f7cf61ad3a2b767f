// How atlas layers are stored on the device (float4 buffers or images), the
// build options that give the kernels the matching access path, and layers
// of a level in either storage.
#pragma once

#include "atlas/patch_layout.h"
#include "cl/runtime.h"
#include "core/vec.h"

#include <string> // for std::string
#include <vector> // for std::vector

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
//! Every texel of a layer, patch-major (LevelLayout::index).
std::vector<Float4> read_layer(Runtime& runtime, const cl::Memory& layer, const LevelLayout& layout,
                               AtlasStorage storage);
//! \throw InputError when `texels` does not hold the level's texel count.
void write_layer(Runtime& runtime, const cl::Memory& layer, const LevelLayout& layout, AtlasStorage storage,
                 const std::vector<Float4>& texels);

} // namespace meshpaint
