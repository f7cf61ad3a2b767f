#include "kernel_traffic.h"

#include "core/format.h"

namespace meshpaint::cli {
namespace {

constexpr double kTexel = 16; // float4

//! Texels the side kernels read per level-1 edge of an n x n tile level:
//! the side row and the row inwards on each side of it (one on a boundary).
double edge_reads(const AtlasTopology& t, int n)
{
  double texels = 0;
  for (const PatchEdge& e : t.edges)
    texels += (e.patch[1] >= 0 ? 3 : 2) * double(n + 1);
  return texels;
}

//! Texels a corner kernel reads: each ring's vertex and its one-ring
//! (the next texel along each slot's side and across its diagonal).
double ring_reads(const AtlasTopology& t)
{
  return double(t.rings.size()) + 2.0 * double(t.slots.size());
}

double tile_texels(const AtlasTopology& t, int level)
{
  return double(level_layout(t.patch_count, level).texels());
}

//! Compact border entries (one per side texel and corner) that the tile
//! kernels copy from, read once per patch side and corner.
double border_entries(const AtlasTopology& t, int n)
{
  return double(t.patch_count) * (4.0 * (n - 1) + 4.0);
}

} // namespace

std::vector<FamilyTraffic> subdivide_traffic(const AtlasTopology& t, int from, int to, const AtlasEvaluator& evaluator)
{
  FamilyTraffic edges{"subdivide edges", {"subdivide_edges"}, 0};
  FamilyTraffic corners{"subdivide corners", {"subdivide_corners", "subdivide_corner_levels"}, 0};
  // In one pass: the first level's rings read once, every level's corners
  // written, a mark per ring written once and read by each later step.
  const bool one_pass = evaluator.corners_in_one_pass() && to - from > 1;
  if (one_pass)
    corners.bytes = kTexel * ring_reads(t) + double(t.rings.size()) * (to - from);
  FamilyTraffic tiles{"subdivide tiles",
                      {"subdivide_tiles", "subdivide_patches", "subdivide_first_step", "subdivide_second_step"},
                      0};
  for (int l = from; l < to; ++l) {
    const int ns = level_layout(t.patch_count, l).n, nd = level_layout(t.patch_count, l + 1).n;
    corners.bytes += one_pass ? kTexel * double(t.rings.size()) : kTexel * (ring_reads(t) + double(t.rings.size()));
    if (evaluator.tiles_walk_sides(l)) {
      // The source tile, the row across each side (in the neighbour's
      // tile), four corners and the written tile.
      tiles.bytes +=
          kTexel * (tile_texels(t, l) + double(t.patch_count) * (4.0 * (ns + 1) + 4.0) + tile_texels(t, l + 1));
    } else {
      edges.bytes += kTexel * (edge_reads(t, ns) + double(t.edges.size()) * (nd - 1));
      tiles.bytes += kTexel * (tile_texels(t, l) + border_entries(t, nd) + tile_texels(t, l + 1));
    }
  }
  return {edges, corners, tiles};
}

std::vector<FamilyTraffic> limit_traffic(const AtlasTopology& t, int level)
{
  const int n = level_layout(t.patch_count, level).n;
  const double texels = tile_texels(t, level);
  FamilyTraffic edges{"limit edges", {"limit_edges"},
                      kTexel * (n > 1 ? edge_reads(t, n) + 2.0 * double(t.edges.size()) * (n - 1) : 0)};
  FamilyTraffic corners{"limit corners", {"limit_corners"}, kTexel * (ring_reads(t) + 2.0 * double(t.rings.size()))};
  // Control points in, positions and normals out, pairs of border entries.
  FamilyTraffic tiles{"limit tiles", {"limit_tiles", "limit_patches"},
                      kTexel * (texels + 2.0 * border_entries(t, n) + 2.0 * texels)};
  FamilyTraffic bounds{"patch bounds", {"patch_bounds"}, kTexel * (texels + double(t.patch_count))};
  return {edges, corners, tiles, bounds};
}

std::vector<FamilyRate> family_rates(const std::vector<FamilyTraffic>& traffic,
                                     const std::map<std::string, double>& kernel_ms, int runs)
{
  std::vector<FamilyRate> out;
  double all_ms = 0, all_bytes = 0;
  for (const FamilyTraffic& f : traffic) {
    double ms = 0;
    bool ran = false;
    for (const std::string& k : f.kernels)
      if (const auto it = kernel_ms.find(k); it != kernel_ms.end()) {
        ms += it->second / runs;
        ran = true;
      }
    if (!ran)
      continue;
    out.push_back({f.family, ms, ms > 0 ? f.bytes / (ms * 1e6) : 0});
    all_ms += ms;
    all_bytes += f.bytes;
  }
  out.push_back({"all", all_ms, all_ms > 0 ? all_bytes / (all_ms * 1e6) : 0});
  return out;
}

void add_family_rows(Table& table, const std::string& what, const std::vector<FamilyRate>& rates, double copy_gbps)
{
  for (const FamilyRate& r : rates)
    table.add({what, r.family, format_fixed(r.ms, 2), format_fixed(r.gbps, 1),
               copy_gbps > 0 ? format_fixed(100 * r.gbps / copy_gbps, 0) + "%" : std::string("-")});
}

std::string family_json(const std::vector<FamilyRate>& rates)
{
  std::string s;
  for (const FamilyRate& r : rates)
    s += std::string(s.empty() ? "" : ",") + "{\"family\":" + json_string(r.family) +
         ",\"ms\":" + std::to_string(r.ms) + ",\"gb_per_s\":" + std::to_string(r.gbps) + "}";
  return "[" + s + "]";
}

} // namespace meshpaint::cli
