#include "atlas/weld.h"

#include "atlas/atlas.h"
#include "core/errors.h"

namespace meshpaint {

std::vector<int> weld_map(const AtlasTopology& topo, const LevelLayout& l)
{
  const int n = l.n, inner = n - 1;
  const int edge_base = int(topo.rings.size());
  const int interior_base = edge_base + int(topo.edges.size()) * inner;
  std::vector<int> map(l.texels(), -1);
  for (int p = 0; p < topo.patch_count; ++p) {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        int id;
        const bool lo_i = i == 0, hi_i = i == n, lo_j = j == 0, hi_j = j == n;
        if ((lo_i || hi_i) && (lo_j || hi_j)) {
          const int corner = lo_j ? (lo_i ? 0 : 1) : (hi_i ? 2 : 3);
          id = topo.patch_corners[p][corner];
        } else if (lo_i || hi_i || lo_j || hi_j) {
          // Position t along side s, as side_frame() in atlas_access.cl runs it.
          const int side = lo_j ? 0 : hi_i ? 1 : hi_j ? 2 : 3;
          const int t = side == 0 ? i : side == 1 ? j : side == 2 ? n - i : n - j;
          const int e = topo.patch_sides[p][side];
          const PatchEdge& pe = topo.edges[e];
          const bool first = pe.patch[0] == p && pe.side[0] == side;
          id = edge_base + e * inner + (first ? t : n - t) - 1;
        } else {
          id = interior_base + p * inner * inner + (j - 1) * inner + (i - 1);
        }
        map[l.index(p, i, j)] = id;
      }
  }
  return map;
}

WeldedSurface weld(const AtlasTopology& topo, const LevelLayout& l, const std::vector<Float4>& positions,
                   const std::vector<Float4>* normals)
{
  WeldedSurface s;
  s.level = l.level;
  const std::vector<int> map = weld_map(topo, l);
  s.points.resize(topo.unique_vertices(l.level));
  if (normals)
    s.normals.resize(s.points.size());
  for (std::size_t t = 0; t < map.size(); ++t) {
    if (map[t] < 0)
      continue;
    s.points[map[t]] = {positions[t][0], positions[t][1], positions[t][2]};
    if (normals)
      s.normals[map[t]] = {(*normals)[t][0], (*normals)[t][1], (*normals)[t][2]};
  }
  s.quads.reserve(std::size_t(topo.patch_count) * l.n * l.n);
  for (int p = 0; p < topo.patch_count; ++p) {
    for (int j = 0; j < l.n; ++j)
      for (int i = 0; i < l.n; ++i)
        s.quads.push_back({map[l.index(p, i, j)], map[l.index(p, i + 1, j)], map[l.index(p, i + 1, j + 1)],
                           map[l.index(p, i, j + 1)]});
  }
  return s;
}

} // namespace meshpaint

namespace meshpaint {

WeldedSurface level_surface(Atlas& atlas, int level, bool limit)
{
  if (limit && level != atlas.max_level())
    throw InputError("limit surfaces come from the atlas's finest level (" +
                     std::to_string(atlas.max_level()) + ")");
  const LevelLayout layout = atlas.layout(level);
  if (!limit)
    return weld(atlas.topology(), layout, atlas.read_positions(level), nullptr);
  const std::vector<Float4> normals = atlas.read_limit_normals();
  return weld(atlas.topology(), layout, atlas.read_limit_positions(), &normals);
}

} // namespace meshpaint
