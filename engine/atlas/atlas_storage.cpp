#include "atlas/atlas_storage.h"

#include "atlas/memory_plan.h"
#include "core/errors.h"

#include <algorithm> // for std::copy_n
#include <cstdlib>   // for std::getenv

namespace meshpaint {
namespace {

//! Calls f(patch-major index, atlas-image index) for the first texel of every
//! tile row.
template <typename F>
void for_each_tile_row(const LevelLayout& l, F&& f)
{
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.tile; ++j)
      f(l.index(p, 0, j), std::size_t((p / l.tiles_x) * l.tile + j) * l.width + (p % l.tiles_x) * l.tile);
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

std::vector<Float4> read_layer(Runtime& runtime, const cl::Memory& layer, const LevelLayout& l, AtlasStorage storage)
{
  std::vector<Float4> out(l.texels());
  if (storage == AtlasStorage::Image) {
    std::vector<Float4> image(l.image_texels());
    runtime.queue().enqueueReadImage(cl::Image2D(layer(), true), CL_TRUE, {0, 0, 0},
                                     {std::size_t(l.width), std::size_t(l.height), 1}, 0, 0, image.data());
    for_each_tile_row(l, [&](std::size_t at, std::size_t in_image) {
      std::copy_n(&image[in_image], l.tile, &out[at]);
    });
  } else {
    runtime.queue().enqueueReadBuffer(cl::Buffer(layer(), true), CL_TRUE, 0, layer_bytes(l, storage), out.data());
  }
  return out;
}

void write_layer(Runtime& runtime, const cl::Memory& layer, const LevelLayout& l, AtlasStorage storage,
                 const std::vector<Float4>& texels)
{
  if (texels.size() != l.texels())
    throw InputError("level " + std::to_string(l.level) + " holds " + std::to_string(l.texels()) +
                     " texels, not " + std::to_string(texels.size()));
  if (storage == AtlasStorage::Image) {
    std::vector<Float4> image(l.image_texels(), Float4{0.f, 0.f, 0.f, 0.f});
    for_each_tile_row(l, [&](std::size_t at, std::size_t in_image) {
      std::copy_n(&texels[at], l.tile, &image[in_image]);
    });
    runtime.queue().enqueueWriteImage(cl::Image2D(layer(), true), CL_TRUE, {0, 0, 0},
                                      {std::size_t(l.width), std::size_t(l.height), 1}, 0, 0, image.data());
  } else {
    runtime.queue().enqueueWriteBuffer(cl::Buffer(layer(), true), CL_TRUE, 0, layer_bytes(l, storage),
                                       texels.data());
  }
}

} // namespace meshpaint
