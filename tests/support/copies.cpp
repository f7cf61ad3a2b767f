#include "support/copies.h"

#include "atlas/weld.h"

#include <cstring> // for std::memcmp

namespace meshpaint::test {

std::size_t differing_copies(const AtlasTopology& topology, const LevelLayout& layout,
                             const std::vector<Float4>& texels)
{
  const std::vector<int> map = weld_map(topology, layout);
  std::vector<long> first(topology.unique_vertices(layout.level), -1);
  std::size_t differing = 0;
  for (std::size_t t = 0; t < map.size(); ++t) {
    if (first[map[t]] < 0)
      first[map[t]] = long(t);
    else if (std::memcmp(&texels[t], &texels[first[map[t]]], sizeof(Float4)) != 0)
      ++differing;
  }
  return differing;
}

} // namespace meshpaint::test
