// Colour paint: paint_dab launches the paint equation on the dab's patches,
// spray_dab lets droplets fall on the surface first.

#include "paint/colour_paint.h"

#include "core/errors.h"
#include "paint/paint_device.h"
#include "paint/spray.h"

#include <limits> // for std::numeric_limits

namespace meshpaint {

void paint_dab(const DabContext& context, const std::vector<int>& patches, const BrushDab& dab)
{
  if (patches.empty())
    return;
  if (context.inside && (dab.alpha[CHANNEL_LABEL] > 0.f || dab.alpha[CHANNEL_DISPLACEMENT] > 0.f)) {
    // Labels and displacement belong to the surface, not to one side.
    BrushDab shared = dab, sided = dab;
    for (int c = 0; c < CHANNEL_COUNT; ++c)
      (c == CHANNEL_LABEL || c == CHANNEL_DISPLACEMENT ? sided : shared).alpha[c] = 0.f;
    context.inside = false;
    paint_dab(context, patches, shared);
    context.inside = true;
    paint_dab(context, patches, sided);
    return;
  }
  context.hooks.remember(patches);
  context.mask_painted = context.mask_painted || dab.alpha[CHANNEL_MASK] > 0.f;
  const PaintState& s = context.state;
  PaintDevice& d = s.device;
  Runtime& rt = s.atlas.runtime();
  const LevelLayout l = s.layout();
  const cl::Buffer list = device_ints(rt.context(), patches);
  d.dab = device_value(rt.context(), dab);
  // Eight patches per work item on CPU devices (paint_patches), for the
  // dabs it takes: those that need no brush normal and no raster.
  const bool lanes = dab.space == SPACE_OBJECT && dab.pattern == PATTERN_NONE && dab.stamp_size[0] == 0;
  const int count = int(patches.size());
  const Atlas::TileLaunch t =
    lanes ? s.atlas.tile_launch(d.paint_dab, d.paint_patches, l, count, PATCH_LANES) : texel_launch(d.paint_dab, l, count);
  launch(rt.queue(), t.kernel, t.global, t.local, s.atlas.limit_positions_layer(),
         s.atlas.limit_normals_layer(), grid(l), list, cl_int(count), d.dab, d.unfold, d.raster, d.stamp,
         context.diffuse(), context.specular(), context.material(), d.locked);
  // No wait here: the next dab's placement reads after it on the same
  // queue, and the stroke's end waits for all of its work.
  context.hooks.phase_done(&StepPhases::transform);
}

void spray_dab(const DabContext& context, const std::vector<int>& patches, const BrushDab& dab,
               const Stroke& stroke, std::uint64_t index, const PlaceDab& place)
{
  // Droplets fall evenly on the screen, so the surface gets fewer per area
  // where it is seen obliquely: by the cosine of the angle to the view.
  const PaintState& s = context.state;
  PaintDevice& d = s.device;
  Runtime& rt = s.atlas.runtime();
  const LevelLayout l = s.layout();
  const int k = stroke.paint().spray_drops;
  std::vector<cl_float2> drops;
  for (const auto& o : spray_offsets(stroke.paint().spray_seed, index, k, dab.radius))
    drops.push_back({{dab.screen_centre[0] + o[0] / dab.centre_depth, dab.screen_centre[1] + o[1] / dab.centre_depth}});
  const cl::Buffer drop_buffer = device_copy(rt.context(), drops);
  cl::Buffer keys(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_uint) * drops.size()),
    texels(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_int) * drops.size()),
    points(rt.context(), CL_MEM_WRITE_ONLY, sizeof(cl_float4) * drops.size());
  cl::CommandQueue& q = rt.queue();
  q.enqueueFillBuffer(keys, cl_uint(0xffffffffu), 0, sizeof(cl_uint) * drops.size());
  q.enqueueFillBuffer(texels, cl_int(std::numeric_limits<cl_int>::max()), 0, sizeof(cl_int) * drops.size());
  d.dab = device_value(rt.context(), dab);
  const cl::Buffer list = device_ints(rt.context(), patches);
  const auto tiles = range_tiles(l, int(patches.size()));
  const cl::Memory &pos = s.atlas.limit_positions_layer(), &nrm = s.atlas.limit_normals_layer();
  for (const int pass : {0, 1})
    launch(q, d.spray_pick, tiles.first, tiles.second, pos, nrm, grid(l), list, int(patches.size()), d.dab,
           s.atlas.limit_bounds(), drop_buffer, k, pass, keys, texels);
  launch(q, d.spray_points, cl::NDRange(round_up(std::size_t(k), kGroup)), cl::NDRange(kGroup), pos, grid(l), texels, k,
         points);
  std::vector<Float4> landed(drops.size());
  q.enqueueReadBuffer(points, CL_TRUE, 0, sizeof(cl_float4) * landed.size(), landed.data());
  // Each droplet is a small object-space dab where it landed.
  Stroke droplet = stroke;
  droplet.brush.space = SPACE_OBJECT;
  droplet.brush.has_camera = false;
  BrushDab drop = dab;
  drop.radius = stroke.paint().spray_size;
  for (const Float4& at : landed) {
    if (at[3] == 0.f)
      continue;
    Vec3 normal;
    const std::vector<int> hit = place(droplet, DabSample{{at[0], at[1], at[2]}, 1.f, {0.f, 0.f, 0.f}}, drop, normal);
    paint_dab(context, hit, drop);
  }
}

void upload_rasters(const PaintState& state, const Stroke& stroke, BrushDab& dab)
{
  const Raster* pattern = stroke.pattern() ? stroke.pattern()->raster.get() : nullptr;
  for (const Raster* r : {pattern, stroke.brush.stamp.get()})
    if (r && (r->width < 1 || r->height < 1 || r->depth < 1 || r->channels < 1 || r->channels > 4 ||
              r->samples.size() != std::size_t(r->width) * r->height * r->depth * r->channels))
      throw InputError("a pattern or brush image of " + std::to_string(r->width) + "x" + std::to_string(r->height) +
                       "x" + std::to_string(r->depth) + " samples of " + std::to_string(r->channels) +
                       " channels does not match its " + std::to_string(r->samples.size()) + " values");
  PaintDevice& d = state.device;
  Runtime& rt = state.atlas.runtime();
  const Raster* r = pattern;
  d.raster = device_copy(rt.context(), r ? r->samples : std::vector<float>());
  dab.raster_size[0] = r ? r->width : 0;
  dab.raster_size[1] = r ? r->height : 0;
  dab.raster_size[2] = r ? r->depth : 0;
  dab.raster_size[3] = r ? r->channels : 0;
  // The stamp as grey: its first channel, or the mean of rgb.
  std::vector<float> grey;
  if (const Raster* s = stroke.brush.stamp.get()) {
    const int c = s->channels;
    for (std::size_t k = 0; k + std::size_t(c) <= s->samples.size(); k += std::size_t(c))
      grey.push_back(c >= 3 ? (s->samples[k] + s->samples[k + 1] + s->samples[k + 2]) / 3.f : s->samples[k]);
    dab.stamp_size[0] = s->width;
    dab.stamp_size[1] = s->height;
  } else {
    dab.stamp_size[0] = dab.stamp_size[1] = 0;
  }
  d.stamp = device_copy(rt.context(), grey);
  // The label guards: locked classes to the device, the chosen class in the dab.
  const auto* p = std::get_if<PaintSettings>(&stroke.settings);
  d.locked = device_ints(rt.context(), p ? p->locked_labels : std::vector<int>{});
  dab.locked_labels = p ? int(p->locked_labels.size()) : 0;
  dab.only_over_label = p ? p->only_over_label : -1;
}

} // namespace meshpaint
