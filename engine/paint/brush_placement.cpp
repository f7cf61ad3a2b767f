// Brush placement: where a dab lands, and the patches it may change.

#include "paint/brush_placement.h"

#include "paint/paint_device.h"

#include "atlas/unfolding.h"
#include "core/marks.h"

#include <cmath>   // for std::lround
#include <cstring> // for std::memcpy
#include <limits>  // for std::numeric_limits

namespace meshpaint {

namespace {

//! Work-groups of the cluster kernels: few clusters hold most of a small
//! brush's work, and small groups let both cores share them.
constexpr std::size_t kClusterGroup = 16;

//! Records, in no particular order and each with its closest texel, of
//! patches with a texel within `radius` of `centre`: among them every
//! patch whose closest texel is the nearest (brush_cull), wherever `hint`
//! points. `follow` as run_appending()'s.
template <typename Follow>
std::vector<CullRecord> cull(const PaintState& state, const Vec3& centre, float radius, const SnapHint& hint,
                             const Follow& follow)
{
  PaintDevice& d = state.device;
  Atlas& atlas = state.atlas;
  const LevelLayout l = state.layout();
  cl_int radius_bits;
  std::memcpy(&radius_bits, &radius, sizeof radius_bits); // brush_cull's nearest distance so far
  const cl_float4 at{{centre[0], centre[1], centre[2], 0.f}};
  // Brushes move little between dabs: the hinted texel bounds the search
  // from the start, so that far patches stop at their bounds.
  const bool seeded = hint.patch >= 0 && hint.patch < l.patches && hint.texel >= 0 && hint.texel < l.tile * l.tile;
  const auto seed = [&] {
    if (seeded)
      launch(atlas.runtime().queue(), d.brush_cull_seed, cl::NDRange(1), cl::NullRange, atlas.limit_positions_layer(),
             grid(l), cl_int(hint.patch), cl_int(hint.texel), at, d.counters);
  };
  const cl_int2 start{{0, radius_bits}};
  const std::size_t most = std::size_t(l.patches); // a record per patch at most
  if (atlas.patch_items()) // CPUs: far clusters stop at their bound
    return run_appending<CullRecord>(atlas.runtime(), d.brush_cull_clusters, cluster_count(l.patches), most,
                                     kClusterGroup, d.culled, d.counters, start, seed, follow,
                                     atlas.limit_positions_layer(), atlas.limit_normals_layer(), grid(l), l.patches,
                                     atlas.limit_bounds(), atlas.limit_cluster_bounds(), at);
  return run_appending<CullRecord>(atlas.runtime(), d.brush_cull, l.patches, most, kGroup, d.culled, d.counters, start,
                                   seed, follow, atlas.limit_positions_layer(), atlas.limit_normals_layer(), grid(l),
                                   l.patches, atlas.limit_bounds(), at);
}

//! Per patch, the sides that come within `radius` of the centre in `at`, a
//! float4 on the device (brush_reach), into the first patches of
//! `open_sides`: at once, or with the queue's next wait.
void reach_sides(const PaintState& state, const cl::Buffer& at, float radius, std::vector<std::uint8_t>& open_sides,
                 bool wait)
{
  PaintDevice& d = state.device;
  Atlas& atlas = state.atlas;
  Runtime& rt = atlas.runtime();
  const LevelLayout l = state.layout();
  if (atlas.patch_items()) {
    const std::size_t clusters = std::size_t(cluster_count(l.patches));
    launch(rt.queue(), d.brush_reach_clusters, cl::NDRange(round_up(clusters, kClusterGroup)),
           cl::NDRange(kClusterGroup), atlas.limit_positions_layer(), grid(l), l.patches, atlas.limit_bounds(),
           atlas.limit_cluster_bounds(), at, radius, d.open_sides);
  } else {
    launch(rt.queue(), d.brush_reach, cl::NDRange(round_up(std::size_t(l.patches), kGroup)), cl::NDRange(kGroup),
           atlas.limit_positions_layer(), grid(l), l.patches, atlas.limit_bounds(), at, radius, d.open_sides);
  }
  rt.queue().enqueueReadBuffer(d.open_sides, wait ? CL_TRUE : CL_FALSE, 0, std::size_t(l.patches), open_sides.data());
}

} // namespace

BrushPlacement::BrushPlacement(const AtlasTopology& topology)
  : neighbours_(std::size_t(topology.patch_count)), open_sides_(std::size_t(topology.patch_count) + 1, REACH_NONE),
    queue_(std::size_t(topology.patch_count) + 1)
{
  for (int p = 0; p < topology.patch_count; ++p)
    for (int s = 0; s < 4; ++s)
      neighbours_[std::size_t(p)][s] = topology.across(p, s);
}

std::vector<int> BrushPlacement::brush_patches(const PaintState& state, const Vec3& point, float radius,
                                               Vec3* centre_out, Vec3* normal_out, float reach, CullRecord* closest)
{
  if (!(reach > 0.f))
    reach = radius;
  // Snap: the closest texel within the radius is the brush centre. The
  // device makes the same choice (brush_snap) and finds the sides within
  // reach of it, so that one wait brings the records and the sides.
  PaintDevice& d = state.device;
  cl_int chosen = -1;
  const auto snap_and_reach = [&] {
    cl::CommandQueue& q = state.atlas.runtime().queue();
    launch(q, d.brush_snap, cl::NDRange(1), cl::NullRange, d.culled.records, d.counters, cl_int(d.culled.capacity),
           d.snap_centre, d.snap_record);
    reach_sides(state, d.snap_centre, reach, open_sides_, false);
    q.enqueueReadBuffer(d.snap_record, CL_FALSE, 0, sizeof chosen, &chosen);
  };
  const std::vector<CullRecord> near = cull(state, point, radius, hint_, snap_and_reach);
  if (near.empty())
    return {};
  const CullRecord* best = &near.front();
  for (const CullRecord& c : near) // nearest, ties to the lowest patch: independent of append order
    if (c.distance < best->distance ||
        (c.distance == best->distance && c.patch < best->patch))
      best = &c;
  hint_ = {best->patch, best->closest_texel};
  const float* snapped = best->closest_position;
  const Vec3 centre{snapped[0], snapped[1], snapped[2]};
  if (centre_out)
    *centre_out = centre;
  if (normal_out)
    *normal_out = {best->closest_normal[0], best->closest_normal[1], best->closest_normal[2]};
  if (closest)
    *closest = *best;

  // The brush reaches the patches connected to the centre's patch through
  // sides that themselves come within the radius: never through the air.
  const int start_patch = best->patch;
  if (chosen != int(best - near.data())) // compared otherwise on the device (denormals): reach from the host's
    reach_sides(state, device_value(state.atlas.runtime().context(), cl_float4{{centre[0], centre[1], centre[2], 0.f}}),
                reach, open_sides_, true);

  // Flood from the centre's patch over the patches within reach,
  // breadth first. A patch's byte in open_sides_ gains kQueued when it is
  // queued: no marks to clear, and no branch on whether a neighbour was
  // seen before (about half were, in no order a predictor learns). A side
  // that is closed or on a border leads to the sentinel after the last
  // patch, whose REACH_NONE already has the bit.
  constexpr std::uint8_t kQueued = 0x40;
  static_assert((REACH_NONE & kQueued) && REACH_NONE > 15, "the sentinel stays out of reach");
  const int sentinel = int(open_sides_.size()) - 1;
  std::uint8_t* open = open_sides_.data();
  int* queue = queue_.data();
  std::size_t tail = open[start_patch] <= 15;
  queue[0] = start_patch;
  open[start_patch] |= kQueued;
  for (std::size_t head = 0; head < tail; ++head) {
    const int p = queue[head];
    const unsigned sides = open[p];
    const std::array<int, 4>& across = neighbours_[std::size_t(p)];
    for (int s = 0; s < 4; ++s) {
      const int q = (sides >> s & 1) && across[std::size_t(s)] >= 0 ? across[std::size_t(s)] : sentinel;
      const unsigned before = open[q];
      queue[tail] = q;
      open[q] = std::uint8_t(before | kQueued);
      tail += before <= 15;
    }
  }
  return in_order(std::vector<int>(queue, queue + tail), std::size_t(sentinel),
                  [open](std::size_t p) { return (open[p] & 0xc0) == kQueued; });
}

void BrushPlacement::hint_snap(const PaintState& state, int patch, double u, double v)
{
  const LevelLayout l = state.layout();
  if (patch < 0 || patch >= l.patches || !(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) {
    hint_ = {};
    return;
  }
  const int i = int(std::lround(u * l.n)), j = int(std::lround(v * l.n));
  hint_ = {patch, j * l.tile + i};
}

float BrushPlacement::distance_to(const PaintState& state, const Vec3& point, float radius)
{
  Vec3 centre;
  if (brush_patches(state, point, radius, &centre).empty())
    return std::numeric_limits<float>::infinity();
  return length(sub(centre, point));
}

std::vector<int> unfold_dab(const PaintState& state, int centre_patch, BrushDab& dab)
{
  PaintDevice& d = state.device;
  Runtime& rt = state.atlas.runtime();
  const Unfolding u =
    unfold(state.atlas.topology(), centre_patch, state.layout().n, dab.centre_texel, dab.radius / dab.texel_size);
  d.unfold = device_copy(rt.context(), u.maps);
  dab.unfolded = int(u.maps.size());
  return u.patches;
}

} // namespace meshpaint
