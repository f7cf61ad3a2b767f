#include "atlas/unfolding.h"

#include "atlas/patch_layout.h"

#include <algorithm>     // for std::min, std::max
#include <array>         // for std::array
#include <climits>       // for INT_MAX
#include <cstdlib>       // for std::abs
#include <unordered_map> // for std::unordered_map

namespace meshpaint {
namespace {

using Point = std::array<int, 2>;

//! The sides a way to a laid patch may cross beyond the straight way: room
//! to go round a vertex or two where patches are not laid straight on
//! (around a vertex of valence 3 a quarter of the plane holds none).
constexpr int kDetour = 4;

//! A map of the plane: a rotation by a multiple of 90 degrees (the images
//! u, v of the axes) and an offset, in tile sides.
struct Map
{
  Point u{1, 0}, v{0, 1}, o{0, 0};
};

Point corner(int k) { return tile_corner(k); }
Point side(int k) { return side_direction(k); }

Point turn(const Map& m, const Point& p) { return {m.u[0] * p[0] + m.v[0] * p[1], m.u[1] * p[0] + m.v[1] * p[1]}; }

Point map_point(const Map& m, const Point& p)
{
  const Point t = turn(m, p);
  return {t[0] + m.o[0], t[1] + m.o[1]};
}

//! a after b.
Map compose(const Map& a, const Map& b) { return {turn(a, b.u), turn(a, b.v), map_point(a, b.o)}; }

//! From the texels of a patch across an edge (its side `from`) to those of
//! the patch whose side `to` it is: the side runs the other way there, as in
//! atlas_access.cl's across_frame(), and inwards there is outwards here.
Map across(int to, int from)
{
  const Point t = side(to), d = side(to + 1), tq = side(from + 2), dq = side(from + 3); // tq = -side(from), ...
  Map m;
  m.u = {t[0] * tq[0] + d[0] * dq[0], t[1] * tq[0] + d[1] * dq[0]};
  m.v = {t[0] * tq[1] + d[0] * dq[1], t[1] * tq[1] + d[1] * dq[1]};
  const Point start = turn(m, corner(from + 1)), at = corner(to);
  m.o = {at[0] - start[0], at[1] - start[1]};
  return m;
}

TexelMap texel_map(const Map& m)
{
  return TexelMap{{m.u[0], m.u[1]}, {m.v[0], m.v[1]}, {m.o[0], m.o[1]}, 1, 0};
}

} // namespace

Unfolding unfold(const AtlasTopology& topology, int centre_patch, int n, const float centre[2], float half)
{
  // Whether the box of two points of a tile under m (tile sides) comes
  // within `reach` texels of the centre in both directions.
  const auto within = [&](const Map& m, const Point& a, const Point& b, float reach) {
    const Point p = map_point(m, a), q = map_point(m, b);
    for (int k = 0; k < 2; ++k) {
      const float lo = float(n * std::min(p[k], q[k])), hi = float(n * std::max(p[k], q[k]));
      if (lo > centre[k] + reach || hi < centre[k] - reach)
        return false;
    }
    return true;
  };
  // Whether it meets the square; one texel of slack, as laying a patch that
  // gets no paint costs only work.
  const float reach = half + 1.f;
  const auto meets = [&](const Map& m, const Point& a, const Point& b) { return within(m, a, b, reach); };

  // Breadth-first across sides: each patch laid the first way found whose
  // tile meets the square and that crosses at most kDetour sides more than
  // the straight way across a grid of square tiles from the centre's tile
  // to that tile, counting no side into a tile that holds the centre. Where
  // more than four patches meet at a vertex the tiles around it overlap in
  // the plane, and a way winding on around such vertices reaches surface
  // far along it while its tile still lies in the square: the detour stops
  // it.
  std::vector<int> laid{centre_patch};
  std::vector<Map> laid_map{Map()};
  std::vector<int> laid_crossings{0};
  std::unordered_map<int, int> rank{{centre_patch, 0}}; // laid patch -> index in `laid`
  for (std::size_t k = 0; k < laid.size(); ++k) {
    const int p = laid[k];
    for (int s = 0; s < 4; ++s) {
      const PatchEdge& e = topology.edges[std::size_t(topology.patch_sides[std::size_t(p)][s])];
      const int w = e.patch[0] == p && e.side[0] == s ? 1 : 0;
      const int q = e.patch[w];
      if (q < 0 || rank.count(q))
        continue;
      const Map m = compose(laid_map[k], across(s, e.side[w]));
      const int crossed = laid_crossings[k] + (within(m, corner(0), corner(2), 0.f) ? 0 : 1);
      const Point a = map_point(m, corner(0)), b = map_point(m, corner(2));
      const int straight = std::abs(std::min(a[0], b[0])) + std::abs(std::min(a[1], b[1]));
      if (crossed > straight + kDetour || !meets(m, corner(0), corner(2)))
        continue;
      rank.emplace(q, int(laid.size()));
      laid.push_back(q);
      laid_map.push_back(m);
      laid_crossings.push_back(crossed);
    }
  }

  // The parts of patch p: its interior when laid; each side and corner with
  // the map of the earliest laid patch storing it. False when no part meets
  // the square.
  const auto parts = [&](int p, PatchUnfolding& out) {
    out = PatchUnfolding{};
    const auto own = rank.find(p);
    bool any = own != rank.end();
    if (any)
      out.part[UNFOLD_INTERIOR] = texel_map(laid_map[std::size_t(own->second)]);
    for (int s = 0; s < 4; ++s) {
      const PatchEdge& e = topology.edges[std::size_t(topology.patch_sides[std::size_t(p)][s])];
      int best = INT_MAX, owner_side = 0;
      for (int k = 0; k < 2; ++k) {
        const auto r = e.patch[k] < 0 ? rank.end() : rank.find(e.patch[k]);
        if (r != rank.end() && r->second < best) {
          best = r->second;
          owner_side = e.side[k];
        }
      }
      if (best == INT_MAX)
        continue;
      Map m = laid_map[std::size_t(best)];
      if (laid[std::size_t(best)] != p || owner_side != s)
        m = compose(m, across(owner_side, s));
      out.part[UNFOLD_SIDE + s] = texel_map(m);
      any = any || meets(m, corner(s), corner(s + 1));
    }
    for (int c = 0; c < 4; ++c) {
      const CornerRing& ring = topology.rings[std::size_t(topology.patch_corners[std::size_t(p)][c])];
      int best = INT_MAX, owner_corner = 0;
      for (int k = 0; k < ring.count; ++k) {
        const CornerSlot& slot = topology.slots[std::size_t(ring.first + k)];
        const auto r = rank.find(slot.patch);
        if (r != rank.end() && r->second < best) {
          best = r->second;
          owner_corner = slot.corner;
        }
      }
      if (best == INT_MAX)
        continue;
      Map m; // the corner's one texel, wherever it lies in this patch
      m.u = m.v = {0, 0};
      m.o = map_point(laid_map[std::size_t(best)], corner(owner_corner));
      out.part[UNFOLD_CORNER + c] = texel_map(m);
      any = any || meets(m, corner(0), corner(0));
    }
    return any;
  };

  Unfolding out;
  out.patches = laid;
  out.maps.resize(laid.size());
  for (std::size_t k = 0; k < laid.size(); ++k)
    parts(laid[k], out.maps[k]);
  // Patches not laid that store a side or corner texel of a laid one: their
  // copies must change with it.
  std::unordered_map<int, char> seen;
  for (std::size_t k = 0; k < laid.size(); ++k) {
    const int p = laid[k];
    std::vector<int> around;
    for (int s = 0; s < 4; ++s) {
      const PatchEdge& e = topology.edges[std::size_t(topology.patch_sides[std::size_t(p)][s])];
      around.push_back(e.patch[0]);
      around.push_back(e.patch[1]);
    }
    for (int c = 0; c < 4; ++c) {
      const CornerRing& ring = topology.rings[std::size_t(topology.patch_corners[std::size_t(p)][c])];
      for (int m = 0; m < ring.count; ++m)
        around.push_back(topology.slots[std::size_t(ring.first + m)].patch);
    }
    for (const int q : around) {
      if (q < 0 || rank.count(q) || !seen.emplace(q, 1).second)
        continue;
      PatchUnfolding u;
      if (parts(q, u)) {
        out.patches.push_back(q);
        out.maps.push_back(u);
      }
    }
  }
  return out;
}

} // namespace meshpaint
