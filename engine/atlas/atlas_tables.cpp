#include "atlas/atlas_tables.h"

#include "cl/launch.h"
#include "core/vec.h"

#include <algorithm> // for std::max, std::stable_sort
#include <array>     // for std::array
#include <cmath>     // for std::cos, std::sin, std::sqrt

namespace meshpaint {
namespace {

//! The corner limit masks' constants for every valence m the rings have, in
//! double precision: two float4 per m, for an interior vertex
//! (cos 2pi/m, sin 2pi/m, lambda, 1 / (4 lambda - 1)) and for a boundary one
//! (cos pi/m, sin pi/m, 1 / (m (3 + cos pi/m)), (cos pi/m + 1) / sin pi/m).
std::vector<Float4> limit_constants(const AtlasTopology& topo)
{
  int most = 1;
  for (const CornerRing& r : topo.rings)
    most = std::max(most, int(r.count));
  std::vector<Float4> out(2 * std::size_t(most + 1), Float4{0.f, 0.f, 0.f, 0.f});
  for (int m = 1; m <= most; ++m) {
    const double theta = 2.0 * M_PI / m, c = std::cos(theta), ch = std::cos(0.5 * theta);
    const double lambda = 0.3125 + 0.0625 * (c + ch * std::sqrt(2.0 * (9.0 + c)));
    out[2 * std::size_t(m)] = {float(c), float(std::sin(theta)), float(lambda), float(1.0 / (4.0 * lambda - 1.0))};
    const double half = M_PI / m, bc = std::cos(half), bs = std::sin(half);
    out[2 * std::size_t(m) + 1] = {float(bc), float(bs), float(1.0 / (m * (3.0 + bc))),
                                   float(bs != 0.0 ? (bc + 1.0) / bs : 0.0)};
  }
  return out;
}

//! AtlasTables::patch_sides() and patch_rings() on the host.
std::pair<std::vector<std::array<int, 4>>, std::vector<std::array<int, 4>>>
border_tables(const AtlasTopology& topo, const std::vector<int>& device_ring)
{
  std::vector<std::array<int, 4>> sides(std::size_t(topo.patch_count)), rings(sides.size());
  for (std::size_t p = 0; p < sides.size(); ++p)
    for (int c = 0; c < 4; ++c) {
      const int e = topo.patch_sides[p][std::size_t(c)];
      const PatchEdge& edge = topo.edges[std::size_t(e)];
      sides[p][std::size_t(c)] = 2 * e + (edge.patch[0] == int(p) && edge.side[0] == c ? 0 : 1);
      rings[p][std::size_t(c)] = device_ring[std::size_t(topo.patch_corners[p][std::size_t(c)])];
    }
  return {sides, rings};
}

} // namespace

AtlasTables::AtlasTables(Runtime& runtime, AtlasTopology topology) : topology_(std::move(topology))
{
  // The corner kernels visit rings in the order of their first patch, so
  // they sweep the atlas instead of jumping. Edges stay in OpenSubdiv's
  // order, which measured better than sorting them by patch.
  std::vector<int> order(topology_.rings.size());
  for (std::size_t v = 0; v < order.size(); ++v)
    order[v] = int(v);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return topology_.slots[topology_.rings[a].first].patch < topology_.slots[topology_.rings[b].first].patch;
  });
  // The slots follow in that order too, a ring's in a row, so that a
  // kernel writing per patch corner (reduce_sectors) lays out what a ring
  // kernel then reads in order; patch_slots says where each corner went.
  std::vector<CornerRing> rings;
  std::vector<CornerSlot> slots;
  std::vector<std::array<int, 4>> patch_slots(std::size_t(topology_.patch_count));
  device_ring_.assign(order.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k) {
    CornerRing r = topology_.rings[order[k]];
    for (int m = 0; m < r.count; ++m) {
      const CornerSlot& s = topology_.slots[std::size_t(r.first + m)];
      patch_slots[std::size_t(s.patch)][std::size_t(s.corner)] = int(slots.size());
      slots.push_back(s);
    }
    r.first = int(slots.size()) - r.count;
    rings.push_back(r);
    device_ring_[order[k]] = int(k);
  }
  edges_ = device_copy(runtime.context(), topology_.edges);
  rings_ = device_copy(runtime.context(), rings);
  valences_ = device_copy(runtime.context(), limit_constants(topology_));
  slots_ = device_copy(runtime.context(), slots);
  patch_slots_ = device_copy(runtime.context(), patch_slots);
  const auto [patch_sides, patch_rings] = border_tables(topology_, device_ring_);
  patch_sides_ = device_copy(runtime.context(), patch_sides);
  patch_rings_ = device_copy(runtime.context(), patch_rings);
  std::vector<std::array<int, 4>> across(std::size_t(topology_.patch_count));
  for (std::size_t p = 0; p < across.size(); ++p)
    for (int c = 0; c < 4; ++c) {
      const PatchEdge& e = topology_.edges[std::size_t(topology_.patch_sides[p][std::size_t(c)])];
      const int k = e.patch[0] == int(p) && e.side[0] == c ? 1 : 0;
      across[p][std::size_t(c)] = e.patch[k] < 0 ? -1 : 4 * e.patch[k] + e.side[k];
    }
  patch_across_ = device_copy(runtime.context(), across);
}

} // namespace meshpaint
