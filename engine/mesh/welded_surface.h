// A quad mesh as the atlas produces it, welded: one vertex per surface point.
#pragma once

#include "core/vec.h"

#include <array>  // for std::array
#include <vector> // for std::vector

namespace meshpaint {

struct WeldedSurface
{
  int level = 1;                         //!< Catmull-Clark steps from the base mesh
  std::vector<Vec3> points;              //!< #vertices
  std::vector<Vec3> normals;             //!< #vertices, or empty
  std::vector<std::array<int, 4>> quads; //!< counter-clockwise
};

} // namespace meshpaint
