// Brush placement: where a dab lands on the surface (the closest limit
// texel within its radius), the patches it may change (those connected to
// the centre through sides within its reach, never through the air), and
// its brush space there.

#include "paint/paint_device.h"

#include "atlas/unfolding.h"
#include "paint/brush_space.h"

#include <cmath>   // for std::sqrt
#include <cstring> // for std::memcpy
#include <limits>  // for std::numeric_limits

namespace meshpaint {

std::vector<CullRecord> PaintSurface::cull(const Vec3& centre, float radius)
{
  PaintDevice& d = *device_;
  const LevelLayout l = atlas_->layout(level_);
  cl_int radius_bits;
  std::memcpy(&radius_bits, &radius, sizeof radius_bits); // brush_cull's nearest distance so far
  return run_appending<CullRecord>(atlas_->runtime(), d.brush_cull, l.patches, kGroup, d.culled, d.counters,
                                   cl_int2{{0, radius_bits}}, atlas_->limit_positions_layer(),
                                   atlas_->limit_normals_layer(), grid(l), l.patches, atlas_->limit_bounds(),
                                   cl_float4{{centre[0], centre[1], centre[2], 0.f}});
}

void PaintSurface::reach_sides(const Vec3& centre, float radius)
{
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  launch(rt.queue(), d.brush_reach, cl::NDRange(round_up(std::size_t(l.patches), kGroup)), cl::NDRange(kGroup),
         atlas_->limit_positions_layer(), grid(l), l.patches, atlas_->limit_bounds(),
         cl_float4{{centre[0], centre[1], centre[2], 0.f}}, radius, d.open_sides);
  rt.queue().enqueueReadBuffer(d.open_sides, CL_TRUE, 0, open_sides_.size(), open_sides_.data());
}

std::vector<int> PaintSurface::brush_patches(const Vec3& point, float radius, Vec3* centre_out, Vec3* normal_out,
                                             float reach, CullRecord* closest)
{
  if (!(reach > 0.f))
    reach = radius;
  // Snap: the closest texel within the radius is the brush centre.
  const std::vector<CullRecord> near = cull(point, radius);
  if (near.empty())
    return {};
  const CullRecord* best = &near.front();
  for (const CullRecord& c : near) // nearest, ties to the lowest patch: independent of append order
    if (c.distance < best->distance ||
        (c.distance == best->distance && c.patch < best->patch))
      best = &c;
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
  reach_sides(centre, reach);

  // Flood from the centre's patch over the patches within reach.
  reached_.begin(open_sides_.size());
  // Breadth first: a patch waits in the queue long enough for the prefetch
  // of its neighbours to arrive (depth first pops it at once).
  // Each patch enters the queue once: room for all, and no push_back.
  std::vector<int> queue(open_sides_.size());
  std::size_t tail = 0;
  const auto visit = [&](int p) {
    if (open_sides_[std::size_t(p)] != REACH_NONE && reached_.mark(std::size_t(p))) {
      queue[tail++] = p;
      __builtin_prefetch(&neighbours_[std::size_t(p)]);
    }
  };
  visit(start_patch);
  for (std::size_t head = 0; head < tail; ++head) {
    const int p = queue[head];
    const std::uint8_t open = open_sides_[std::size_t(p)];
    for (int s = 0; s < 4; ++s)
      if ((open >> s & 1) && neighbours_[std::size_t(p)][s] >= 0)
        visit(neighbours_[std::size_t(p)][s]);
  }
  queue.resize(tail);
  return marked_in_order(std::move(queue), reached_, open_sides_.size());
}

float PaintSurface::distance_to(const Vec3& point, float radius)
{
  Vec3 centre;
  if (brush_patches(point, radius, &centre).empty())
    return std::numeric_limits<float>::infinity();
  return length(sub(centre, point));
}

std::vector<int> PaintSurface::place(const Stroke& stroke, const DabSample& sample, BrushDab& dab, Vec3& normal)
{
  // A tangent or screen footprint runs further than the radius in space on
  // surface turned from the brush: the search for it goes that far, at most.
  const float reach = dab.radius * (stroke.brush.space == SPACE_SCREEN ? 4.f : stroke.brush.space == SPACE_OBJECT ? 1.f : 2.f);
  Vec3 centre;
  CullRecord closest{};
  std::vector<int> patches = brush_patches(sample.centre, dab.radius, &centre, &normal, reach, &closest);
  if (patches.empty())
    return patches;
  for (int k = 0; k < 3; ++k)
    dab.centre[k] = centre[k];
  dab.unfolded = 0;
  if (!aim(stroke, sample.centre, normal, sample.heading, closest, dab))
    return {};
  if (stroke.brush.space == SPACE_PARAMETER)
    return unfold_dab(closest.patch, dab);
  return patches;
}

std::vector<int> PaintSurface::unfold_dab(int centre_patch, BrushDab& dab)
{
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const Unfolding u =
    unfold(atlas_->topology(), centre_patch, atlas_->layout(level_).n, dab.centre_texel, dab.radius / dab.texel_size);
  if (d.unfold_capacity < u.maps.size()) {
    d.unfold_capacity = u.maps.size();
    d.unfold = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(PatchUnfolding) * d.unfold_capacity);
  }
  // Blocking: the host copy goes when this returns.
  rt.queue().enqueueWriteBuffer(d.unfold, CL_TRUE, 0, sizeof(PatchUnfolding) * u.maps.size(), u.maps.data());
  dab.unfolded = int(u.maps.size());
  return u.patches;
}

bool PaintSurface::aim(const Stroke& stroke, const Vec3& point, const Vec3& normal, const Vec3& heading,
                       const CullRecord& closest, BrushDab& dab)
{
  // The side a two-sided surface is painted on: the one the eye sees for a
  // screen brush, else the one the stroke's point lies on.
  const ToolFamily family = tool_family(stroke);
  const bool colours = family == ToolFamily::Paint || family == ToolFamily::ColourFilter;
  inside_ = false;
  if (two_sided_ && colours) {
    const Vec3 from = stroke.brush.space == SPACE_SCREEN && stroke.brush.has_camera ? stroke.brush.camera.position : point;
    const float seen = dot(sub(from, Vec3{dab.centre[0], dab.centre[1], dab.centre[2]}), normal);
    inside_ = stroke.brush.side == 2 || (stroke.brush.side == 0 && seen < 0.f);
  }
  dab.side_sign = inside_ ? -1.f : 1.f;
  if (stroke.brush.has_camera && !(two_sided_ && colours) && open_) {
    // A surface of one side shows it to the eye whichever way its faces
    // are wound: the side facing the camera where the stroke starts is the
    // front for the whole stroke, so inward-wound scans paint as outward ones.
    if (open_->facing_side == 0.f) {
      const Vec3 to_eye = sub(stroke.brush.camera.position, Vec3{dab.centre[0], dab.centre[1], dab.centre[2]});
      open_->facing_side = dot(to_eye, normal) < 0.f ? -1.f : 1.f;
    }
    dab.side_sign = open_->facing_side;
  }
  dab.space = stroke.brush.space;
  dab.paint_backfaces = stroke.brush.paint_backfaces ? 1 : 0;
  for (int k = 0; k < 3; ++k)
    dab.centre_normal[k] = normal[k];
  stamp_axes(normal, heading, dab);
  if (stroke.brush.has_camera) {
    camera_frame(stroke.brush.camera, dab);
    if (stroke.brush.space == SPACE_SCREEN && at_silhouette(dab, normal))
      return false;
  }
  if (stroke.brush.space == SPACE_PARAMETER) {
    const LevelLayout l = atlas_->layout(level_);
    cl_float4 bound;
    atlas_->runtime().queue().enqueueReadBuffer(atlas_->limit_bounds(), CL_TRUE, sizeof(cl_float4) * closest.patch,
                                                sizeof bound, &bound);
    dab.centre_texel[0] = float(closest.closest_texel % l.tile);
    dab.centre_texel[1] = float(closest.closest_texel / l.tile);
    dab.texel_size = float(std::sqrt(2.0) * bound.s[3] / l.n); // the tile's side over its texels
  }
  return true;
}

} // namespace meshpaint
