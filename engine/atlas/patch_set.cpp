#include "atlas/patch_set.h"

namespace meshpaint {

PatchSet PatchSetMaker::lists(const std::vector<int>& patches, Reach reach)
{
  const AtlasTopology& topo = tables_.topology();
  patch_marks_.begin(std::size_t(topo.patch_count));
  std::vector<int> listed;
  listed.reserve(patches.size());
  for (const int p : patches)
    if (patch_marks_.mark(std::size_t(p)))
      listed.push_back(p);
  return marked_set(marked_in_order(std::move(listed), patch_marks_, std::size_t(topo.patch_count)), reach);
}

PatchSet PatchSetMaker::neighbourhood(const std::vector<int>& changed)
{
  // The set's edges and rings are every side and corner of it.
  return marked_set(tables_.topology().corner_neighbourhood(changed, 1, patch_marks_, ring_seen_), Reach::Any);
}

std::uint8_t PatchSetMaker::outside_bits(int p)
{
  const AtlasTopology& topo = tables_.topology();
  std::uint8_t corners = 0;
  for (int c = 0; c < 4; ++c)
    if (ring_outside(topo.patch_corners[std::size_t(p)][std::size_t(c)]))
      corners |= std::uint8_t(1u << c);
  // Side s runs from corner s to corner s + 1, and the patch across it is
  // in both corners' rings (one fan each): only where both rings reach
  // outside can it be outside, so most patches look up no side at all.
  std::uint8_t bits = std::uint8_t(corners << 4);
  for (int s = 0; s < 4; ++s)
    if ((corners >> s & 1) && (corners >> ((s + 1) & 3) & 1)) {
      const int q = topo.across(p, s);
      if (q >= 0 && !patch_marks_.marked(std::size_t(q)))
        bits |= std::uint8_t(1u << s);
    }
  return bits;
}

bool PatchSetMaker::ring_outside(int v)
{
  // About four patches meet at a corner: each ring is scanned once.
  if (ring_known_.mark(std::size_t(v))) {
    const AtlasTopology& topo = tables_.topology();
    const CornerRing& ring = topo.rings[std::size_t(v)];
    bool outside = false;
    for (int m = 0; m < ring.count && !outside; ++m)
      outside = !patch_marks_.marked(std::size_t(topo.slots[std::size_t(ring.first + m)].patch));
    ring_outside_[std::size_t(v)] = outside;
  }
  return ring_outside_[std::size_t(v)];
}

void PatchSetMaker::begin_outside()
{
  ring_known_.begin(tables_.topology().rings.size());
  ring_outside_.resize(tables_.topology().rings.size());
}

PatchSet PatchSetMaker::marked_set(std::vector<int> patches, Reach reach)
{
  const AtlasTopology& topo = tables_.topology();
  PatchSet set;
  set.form = PatchSet::Form::Lists;
  set.patches = std::move(patches);
  edge_marks_.begin(topo.edges.size());
  ring_marks_.begin(topo.rings.size());
  if (reach == Reach::All) {
    set.outside.reserve(set.patches.size());
    begin_outside();
  }
  for (const int p : set.patches) {
    // By Reach::All, a side or corner shared with a patch outside stays out.
    const std::uint8_t outside = reach == Reach::All ? outside_bits(p) : 0;
    if (reach == Reach::All)
      set.outside.push_back(outside);
    for (int s = 0; s < 4; ++s) {
      const int e = topo.patch_sides[std::size_t(p)][std::size_t(s)];
      if (edge_marks_.mark(std::size_t(e)) && !(outside >> s & 1))
        set.edges.push_back(e);
      const int v = topo.patch_corners[std::size_t(p)][std::size_t(s)];
      if (ring_marks_.mark(std::size_t(v)) && !(outside >> (4 + s) & 1)) {
        set.rings.push_back(tables_.device_ring(v));
        set.corners.push_back(v);
      }
    }
  }
  return set;
}

std::vector<std::uint8_t> PatchSetMaker::shared_outside(const std::vector<int>& patches)
{
  patch_marks_.begin(std::size_t(tables_.topology().patch_count));
  for (const int p : patches)
    patch_marks_.mark(std::size_t(p));
  begin_outside();
  std::vector<std::uint8_t> out(patches.size());
  for (std::size_t k = 0; k < patches.size(); ++k)
    out[k] = outside_bits(patches[k]);
  return out;
}

} // namespace meshpaint
