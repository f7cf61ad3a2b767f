// The size of each level of the atlas, and where tiles lie in it.
#pragma once

#include "atlas_types.h" // for PATCH_CLUSTER

#include <array>   // for std::array
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

//! Corner k (0..3, counter-clockwise from the patch's first) of a tile in
//! tile sides, and the direction of side k, which runs from corner k to
//! corner k + 1: the host's copy of atlas_access.cl's tables.
constexpr std::array<int, 2> tile_corner(int k)
{
  constexpr int c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return {c[k & 3][0], c[k & 3][1]};
}
constexpr std::array<int, 2> side_direction(int k)
{
  constexpr int d[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  return {d[k & 3][0], d[k & 3][1]};
}

//! Layout of `level` (>= 1) for `patches` patches, tiles as square as possible.
LevelLayout level_layout(int patches, int level);

//! Clusters of PATCH_CLUSTER consecutive patches (AtlasEvaluator::cluster_bounds()).
inline int cluster_count(int patches) { return (patches + PATCH_CLUSTER - 1) / PATCH_CLUSTER; }

} // namespace meshpaint
