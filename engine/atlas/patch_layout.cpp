#include "atlas/patch_layout.h"

#include <cmath> // for std::ceil, std::sqrt

namespace meshpaint {

LevelLayout level_layout(int patches, int level)
{
  LevelLayout l;
  l.level = level;
  l.patches = patches;
  l.n = 1 << (level - 1);
  l.tile = l.n + 1;
  l.tiles_x = int(std::ceil(std::sqrt(double(patches))));
  l.tiles_y = (patches + l.tiles_x - 1) / l.tiles_x;
  l.width = l.tiles_x * l.tile;
  l.height = l.tiles_y * l.tile;
  return l;
}

} // namespace meshpaint
