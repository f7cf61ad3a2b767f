// Sampled images for pattern paint and brush stamps.
#pragma once

#include <vector> // for std::vector

namespace meshpaint {

//! A 2D image (depth 1) or a 3D voxel array: `channels` floats per sample,
//! 0..1, x fastest, then y (upwards), then z.
struct Raster
{
  int width = 0, height = 0, depth = 1, channels = 1;
  std::vector<float> samples;

  bool empty() const { return samples.empty(); }
};

} // namespace meshpaint
