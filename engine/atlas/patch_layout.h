// Where each patch's tile lies in the atlas of a level, and what it costs.
#pragma once

#include <cstddef> // for std::size_t

namespace meshpaint {

//! Highest level the engine accepts at all (the device usually stops earlier).
constexpr int kMaxLevel = 12;

//! Tiles of (n+1) x (n+1) texels, n = 2^(level-1), tiles_x per row. Every
//! level uses the same tile grid, so patch p sits in the same tile cell.
struct LevelLayout
{
  int level = 1;
  int n = 1;
  int tile = 2;
  int tiles_x = 1;
  int tiles_y = 1;
  int width = 2;
  int height = 2;

  std::size_t texels() const { return std::size_t(width) * std::size_t(height); }
  //! One float4 layer (positions, normals, ...).
  std::size_t layer_bytes() const { return texels() * 16; }
};

//! Layout of `level` (>= 1) for `patches` patches, tiles as square as possible.
LevelLayout level_layout(int patches, int level);

} // namespace meshpaint
