// Sampled images for pattern paint and brush stamps.
#pragma once

#include <cstdint> // for std::uint64_t
#include <vector>  // for std::vector

namespace meshpaint {

//! Most samples (pixels or voxels x channels) a pattern or stamp file may
//! hold: a 4096 x 4096 RGBA image, 256 MiB as floats. Checked from the
//! file's header, before it is decoded.
constexpr std::uint64_t kMaxRasterSamples = std::uint64_t(1) << 26;

//! A 2D image (depth 1) or a 3D voxel array: `channels` floats per sample,
//! 0..1, x fastest, then y (upwards), then z.
struct Raster
{
  int width = 0, height = 0, depth = 1, channels = 1;
  std::vector<float> samples;

  bool empty() const { return samples.empty(); }
};

} // namespace meshpaint
