#include "atlas/welded_neighbours.h"

#include "atlas/weld.h"

namespace meshpaint {

namespace {

//! Texel (t, d) of a patch seen from its side or corner `s`, as side_frame()
//! in atlas_access.cl: t along the side, d inwards.
std::size_t frame_texel(const LevelLayout& l, int patch, int s, int t, int d)
{
  const auto o = tile_corner(s), dt = side_direction(s), dd = side_direction(s + 1);
  return l.index(patch, o[0] * l.n + t * dt[0] + d * dd[0], o[1] * l.n + t * dt[1] + d * dd[1]);
}

//! The same across an edge, as across_frame(): position t of this side is
//! n - t of that one, and d < 0 reaches -d texels into it.
std::size_t across_texel(const LevelLayout& l, int patch, int s, int t, int d)
{
  const auto o = tile_corner(s + 1), dt = side_direction(s), dd = side_direction(s + 1);
  return l.index(patch, o[0] * l.n - t * dt[0] - d * dd[0], o[1] * l.n - t * dt[1] - d * dd[1]);
}

} // namespace

WeldedNeighbours welded_neighbours(const AtlasTopology& topo, const LevelLayout& l)
{
  WeldedNeighbours w;
  w.inner = l.n - 1;
  w.edge_base = int(topo.rings.size());
  w.interior_base = w.edge_base + int(topo.edges.size()) * w.inner;
  w.vertex_of = weld_map(topo, l);
  const std::size_t count = topo.unique_vertices(l.level);
  w.texel.reserve(count);
  w.around.reserve(count - topo.rings.size());
  // Vertices in weld_map()'s order: corners, side texels edge by edge, interiors.
  for (const CornerRing& ring : topo.rings) {
    const CornerSlot& a = topo.slots[std::size_t(ring.first)];
    const CornerSlot& b = topo.slots[std::size_t(ring.first + ring.count - 1)];
    w.texel.push_back(int(frame_texel(l, a.patch, a.corner, 0, 0)));
    w.first.push_back(int(w.ring.size()));
    if (ring.boundary && ring.count > 1) {
      w.ring.push_back(w.vertex_of[frame_texel(l, a.patch, a.corner, 1, 0)]);
      w.ring.push_back(w.vertex_of[frame_texel(l, b.patch, b.corner, 0, 1)]);
    } else if (!ring.boundary) {
      for (int m = 0; m < ring.count; ++m) {
        const CornerSlot& s = topo.slots[std::size_t(ring.first + m)];
        w.ring.push_back(w.vertex_of[frame_texel(l, s.patch, s.corner, 1, 0)]);
      }
    }
  }
  w.first.push_back(int(w.ring.size()));
  const auto add = [&](std::size_t texel, std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
    w.texel.push_back(int(texel));
    w.around.push_back({w.vertex_of[a], w.vertex_of[b], w.vertex_of[c], w.vertex_of[d]});
  };
  for (const PatchEdge& e : topo.edges)
    for (int t = 1; t < l.n; ++t) {
      const int p = e.patch[0], s = e.side[0];
      const std::size_t at = frame_texel(l, p, s, t, 0), before = frame_texel(l, p, s, t - 1, 0),
                        after = frame_texel(l, p, s, t + 1, 0);
      if (e.patch[1] < 0)
        add(at, before, after, before, after);
      else
        add(at, before, after, frame_texel(l, p, s, t, 1), across_texel(l, e.patch[1], e.side[1], t, -1));
    }
  for (int p = 0; p < topo.patch_count; ++p)
    for (int j = 1; j < l.n; ++j)
      for (int i = 1; i < l.n; ++i)
        add(l.index(p, i, j), l.index(p, i - 1, j), l.index(p, i + 1, j), l.index(p, i, j - 1),
            l.index(p, i, j + 1));
  return w;
}

std::vector<int> WeldedNumbering::moved(const std::vector<int>& patches, const std::vector<int>& edges,
                                        const std::vector<int>& corners) const
{
  const int per_patch = inner * inner;
  std::vector<int> out;
  out.reserve(moved_count(patches.size(), edges.size(), corners.size()));
  out.insert(out.end(), corners.begin(), corners.end());
  for (const int e : edges)
    for (int t = 0; t < inner; ++t)
      out.push_back(edge_base + e * inner + t);
  for (const int p : patches)
    for (int k = 0; k < per_patch; ++k)
      out.push_back(interior_base + p * per_patch + k);
  return out;
}

} // namespace meshpaint
