#include "atlas/patch_set.h"

#include <algorithm> // for std::sort, std::unique, std::lower_bound

namespace meshpaint {

PatchSet PatchSetMaker::lists(const std::vector<int>& patches, Reach reach)
{
  const AtlasTopology& topo = tables_.topology();
  patch_marks_.begin(std::size_t(topo.patch_count));
  std::vector<int> listed(patches.size());
  std::size_t size = 0;
  for (const int p : patches) {
    listed[size] = p;
    size += patch_marks_.mark(std::size_t(p));
  }
  listed.resize(size);
  return marked_set(marked_in_order(std::move(listed), patch_marks_, std::size_t(topo.patch_count)), reach);
}

std::vector<int> PatchSetMaker::corner_neighbourhood(const std::vector<int>& patches)
{
  return tables_.topology().corner_neighbourhood(patches, patch_marks_, ring_seen_);
}

PatchSet PatchSetMaker::neighbourhood(const std::vector<int>& changed)
{
  // The set's edges and rings are every side and corner of it.
  return marked_set(corner_neighbourhood(changed), Reach::Any);
}

std::vector<std::uint8_t> PatchSetMaker::outside_of(const std::vector<int>& patches)
{
  // A ring reaches outside the set when fewer of its slots hold a patch of
  // the set than it has slots: each patch counts itself at its four
  // corners, instead of a walk of every ring with a branch per slot.
  const AtlasTopology& topo = tables_.topology();
  std::vector<std::uint8_t> out(patches.size());
  ring_held_.resize(topo.rings.size()); // zeros between calls: nothing below throws
  for (const int p : patches)
    for (const int v : topo.patch_corners[std::size_t(p)])
      ++ring_held_[std::size_t(v)];
  for (std::size_t k = 0; k < patches.size(); ++k) {
    const int p = patches[k];
    const std::array<int, 4>& corner = topo.patch_corners[std::size_t(p)];
    unsigned corners = 0;
    for (int c = 0; c < 4; ++c) {
      const std::size_t v = std::size_t(corner[std::size_t(c)]);
      corners |= unsigned(ring_held_[v] != topo.rings[v].count) << c;
    }
    // Side s runs from corner s to corner s + 1, and the patch across it is
    // in both corners' rings (one fan each): only where both rings reach
    // outside can it be outside, so most patches look up no side at all.
    unsigned bits = corners << 4;
    for (int s = 0; s < 4; ++s)
      if ((corners >> s & 1) && (corners >> ((s + 1) & 3) & 1)) {
        const int q = topo.across(p, s);
        if (q >= 0 && !patch_marks_.marked(std::size_t(q)))
          bits |= 1u << s;
      }
    out[k] = std::uint8_t(bits);
  }
  for (const int p : patches)
    for (const int v : topo.patch_corners[std::size_t(p)])
      ring_held_[std::size_t(v)] = 0;
  return out;
}

PatchSet PatchSetMaker::marked_set(std::vector<int> patches, Reach reach)
{
  const AtlasTopology& topo = tables_.topology();
  PatchSet set;
  set.form = PatchSet::Form::Lists;
  set.patches = std::move(patches);
  // By Reach::All, a side or corner shared with a patch outside stays out.
  if (reach == Reach::All)
    set.outside = outside_of(set.patches);
  edge_marks_.begin(topo.edges.size());
  ring_marks_.begin(topo.rings.size());
  // Every side and corner is written at its list's end and kept by a count
  // of whether it is new and in, rather than pushed behind a branch.
  const std::size_t most = 4 * set.patches.size();
  set.edges.resize(most);
  set.corners.resize(most);
  std::size_t edges = 0, corners = 0;
  for (std::size_t k = 0; k < set.patches.size(); ++k) {
    const std::size_t p = std::size_t(set.patches[k]);
    const unsigned outside = reach == Reach::All ? set.outside[k] : 0u;
    for (int s = 0; s < 4; ++s) {
      const int e = topo.patch_sides[p][std::size_t(s)], v = topo.patch_corners[p][std::size_t(s)];
      set.edges[edges] = e;
      edges += edge_marks_.mark(std::size_t(e)) & !(outside >> s & 1);
      set.corners[corners] = v;
      corners += ring_marks_.mark(std::size_t(v)) & !(outside >> (4 + s) & 1);
    }
  }
  set.edges.resize(edges);
  set.corners.resize(corners);
  set.rings.resize(corners);
  for (std::size_t k = 0; k < corners; ++k)
    set.rings[k] = tables_.device_ring(set.corners[k]);
  return set;
}

std::vector<std::uint8_t> PatchSetMaker::shared_outside(const std::vector<int>& patches)
{
  patch_marks_.begin(std::size_t(tables_.topology().patch_count));
  bool repeats = false;
  for (const int p : patches)
    repeats |= !patch_marks_.mark(std::size_t(p));
  if (!repeats)
    return outside_of(patches);
  // outside_of() counts each patch once.
  std::vector<int> once = patches;
  std::sort(once.begin(), once.end());
  once.erase(std::unique(once.begin(), once.end()), once.end());
  const std::vector<std::uint8_t> bits = outside_of(once);
  std::vector<std::uint8_t> out(patches.size());
  for (std::size_t k = 0; k < patches.size(); ++k)
    out[k] = bits[std::size_t(std::lower_bound(once.begin(), once.end(), patches[k]) - once.begin())];
  return out;
}

} // namespace meshpaint
