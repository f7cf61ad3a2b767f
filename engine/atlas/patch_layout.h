// The size of each level of the atlas, and where tiles lie in it.
#pragma once

#include <cstddef> // for std::size_t

namespace meshpaint {

//! Highest level the engine accepts at all (the device usually stops earlier).
constexpr int kMaxLevel = 12;

//! One tile of (n+1) x (n+1) texels per patch, n = 2^(level-1).
//! Host-side arrays and device buffers hold the tiles patch after patch
//! (texel (p, i, j) at (p * tile + j) * tile + i). Device images lay the
//! tiles row-major in a width x height atlas, tiles_x tiles per row; every
//! level uses the same tile grid.
struct LevelLayout
{
  int level = 1;
  int patches = 0;
  int n = 1;
  int tile = 2;
  int tiles_x = 1;
  int tiles_y = 1;
  int width = 2;
  int height = 2;

  //! Texels in patch-major order (host arrays, device buffers).
  std::size_t texels() const { return std::size_t(patches) * std::size_t(tile) * std::size_t(tile); }
  std::size_t index(int patch, int i, int j) const
  {
    return (std::size_t(patch) * std::size_t(tile) + std::size_t(j)) * std::size_t(tile) + std::size_t(i);
  }
  //! Texels of the atlas image, unused tiles included.
  std::size_t image_texels() const { return std::size_t(width) * std::size_t(height); }
};

//! Layout of `level` (>= 1) for `patches` patches, tiles as square as possible.
LevelLayout level_layout(int patches, int level);

} // namespace meshpaint
