#include "atlas/tile_ranges.h"

#include "cl/launch.h"

#include <algorithm> // for std::max

namespace meshpaint {
namespace {

// Work items per group of the atlas-wide kernels: a few whole tiles.
constexpr std::size_t kGroupTexels = 256;

//! `count` squares of side x side work items, stacked along the second axis.
std::pair<cl::NDRange, cl::NDRange> range_squares(std::size_t side, int count)
{
  if (side > kGroupTexels)
    return {cl::NDRange(side, side * std::size_t(count)), cl::NullRange};
  const std::size_t rows = std::max<std::size_t>(1, kGroupTexels / side);
  return {cl::NDRange(side, round_up(side * std::size_t(count), rows)), cl::NDRange(side, rows)};
}

} // namespace

std::pair<cl::NDRange, cl::NDRange> range_tiles(const LevelLayout& l, int count)
{
  return range_squares(std::size_t(l.tile), count);
}

std::pair<cl::NDRange, cl::NDRange> range_interiors(const LevelLayout& l, int count)
{
  return range_squares(std::size_t(l.n - 1), count);
}

} // namespace meshpaint
