// Colour brushes: the paint equation under a dab (paint, label, wash, dip),
// spray droplets, and the smear brush's pick-up; the stroke's pattern,
// brush image and label guards for the kernels.

#include "paint/paint_device.h"

#include "paint/spray.h"

#include <algorithm> // for std::max
#include <limits>    // for std::numeric_limits

namespace meshpaint {

void PaintSurface::paint(const std::vector<int>& patches, const BrushDab& dab)
{
  if (patches.empty())
    return;
  if (inside_ && (dab.alpha[CHANNEL_LABEL] > 0.f || dab.alpha[CHANNEL_DISPLACEMENT] > 0.f)) {
    // Labels and displacement belong to the surface, not to one side.
    BrushDab shared = dab, sided = dab;
    for (int c = 0; c < CHANNEL_COUNT; ++c)
      (c == CHANNEL_LABEL || c == CHANNEL_DISPLACEMENT ? sided : shared).alpha[c] = 0.f;
    inside_ = false;
    paint(patches, shared);
    inside_ = true;
    paint(patches, sided);
    return;
  }
  remember(patches);
  mask_painted_ = mask_painted_ || dab.alpha[CHANNEL_MASK] > 0.f;
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  if (d.active_capacity < patches.size()) {
    d.active_capacity = std::max(patches.size(), std::size_t(l.patches < 1024 ? l.patches : 1024));
    d.active = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(cl_int) * d.active_capacity);
  }
  // Blocking: the host memory behind both may be gone if a launch throws.
  rt.queue().enqueueWriteBuffer(d.active, CL_TRUE, 0, sizeof(cl_int) * patches.size(), patches.data());
  rt.queue().enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
  const auto tiles = range_tiles(l, int(patches.size()));
  launch(rt.queue(), d.paint_dab, tiles.first, tiles.second, atlas_->limit_positions_layer(),
         atlas_->limit_normals_layer(), grid(l), d.active, cl_int(patches.size()), d.dab, d.unfold, d.raster, d.stamp,
         diffuse_buffer(), specular_buffer(), material_buffer(), d.locked);
  rt.queue().finish();
  phase_done(&StepPhases::transform);
}

void PaintSurface::spray(const std::vector<int>& patches, const BrushDab& dab, const Stroke& stroke,
                         std::uint64_t index)
{
  // Droplets fall evenly on the screen, so the surface gets fewer per area
  // where it is seen obliquely: by the cosine of the angle to the view.
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  const int k = stroke.paint().spray_drops;
  std::vector<cl_float2> drops;
  for (const auto& o : spray_offsets(stroke.paint().spray_seed, index, k, dab.radius))
    drops.push_back({{dab.screen_centre[0] + o[0] / dab.centre_depth, dab.screen_centre[1] + o[1] / dab.centre_depth}});
  const cl::Buffer drop_buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(cl_float2) * drops.size(),
                               drops.data());
  cl::Buffer keys(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_uint) * drops.size()),
    texels(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_int) * drops.size()),
    points(rt.context(), CL_MEM_WRITE_ONLY, sizeof(cl_float4) * drops.size());
  cl::CommandQueue& q = rt.queue();
  q.enqueueFillBuffer(keys, cl_uint(0xffffffffu), 0, sizeof(cl_uint) * drops.size());
  q.enqueueFillBuffer(texels, cl_int(std::numeric_limits<cl_int>::max()), 0, sizeof(cl_int) * drops.size());
  q.enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
  const cl::Buffer list = device_ints(rt.context(), patches);
  const auto tiles = range_tiles(l, int(patches.size()));
  const cl::Memory &pos = atlas_->limit_positions_layer(), &nrm = atlas_->limit_normals_layer();
  for (const int pass : {0, 1})
    launch(q, d.spray_pick, tiles.first, tiles.second, pos, nrm, grid(l), list, int(patches.size()), d.dab, atlas_->limit_bounds(),
           drop_buffer, k, pass, keys, texels);
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
    paint(hit, drop);
  }
}

void PaintSurface::smear(const std::vector<int>& patches, BrushDab dab, std::optional<std::array<Float4, 2>>& carried)
{
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  // Lay down what the previous dab picked up, then pick up from here.
  if (carried) {
    for (int k = 0; k < 4; ++k) {
      dab.value[CHANNEL_DIFFUSE][k] = (*carried)[0][k];
      dab.value[CHANNEL_SPECULAR][k] = (*carried)[1][k];
    }
    for (int c = 0; c < CHANNEL_COUNT; ++c)
      dab.alpha[c] = c == CHANNEL_DIFFUSE || c == CHANNEL_SPECULAR ? 1.f : 0.f;
    dab.op = PAINT_OP_COPY;
    dab.pattern = PATTERN_NONE;
    paint(patches, dab);
  }
  const cl::Buffer list = device_ints(rt.context(), patches);
  const int count = int(patches.size());
  const std::size_t items = kGroup, texels = std::size_t(count) * l.tile * l.tile;
  const std::size_t groups = (texels + items - 1) / items;
  cl::Buffer partial(rt.context(), CL_MEM_WRITE_ONLY, 3 * groups * sizeof(Float4));
  rt.queue().enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
  launch(rt.queue(), d.dab_pickup, cl::NDRange(groups * items), cl::NDRange(items), atlas_->limit_positions_layer(),
         atlas_->limit_normals_layer(),
         grid(l), list, count, d.dab, d.unfold, d.stamp, diffuse_buffer(), specular_buffer(), partial,
         cl::Local(3 * items * sizeof(Float4)));
  std::vector<Float4> sums(3 * groups);
  rt.queue().enqueueReadBuffer(partial, CL_TRUE, 0, sums.size() * sizeof(Float4), sums.data());
  double acc[2][4] = {}, weight = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    for (int k = 0; k < 4; ++k) {
      acc[0][k] += sums[3 * g][k];
      acc[1][k] += sums[3 * g + 1][k];
    }
    weight += sums[3 * g + 2][0];
  }
  if (weight > 0) {
    std::array<Float4, 2> load;
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < 4; ++k)
        load[std::size_t(c)][k] = float(acc[c][k] / weight);
    carried = load;
  }
}

void PaintSurface::upload_rasters(const Stroke& stroke, BrushDab& dab)
{
  const Raster* pattern = stroke.pattern() ? stroke.pattern()->raster.get() : nullptr;
  for (const Raster* r : {pattern, stroke.brush.stamp.get()})
    if (r && (r->width < 1 || r->height < 1 || r->depth < 1 || r->channels < 1 || r->channels > 4 ||
              r->samples.size() != std::size_t(r->width) * r->height * r->depth * r->channels))
      throw InputError("a pattern or brush image of " + std::to_string(r->width) + "x" + std::to_string(r->height) +
                       "x" + std::to_string(r->depth) + " samples of " + std::to_string(r->channels) +
                       " channels does not match its " + std::to_string(r->samples.size()) + " values");
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const auto upload = [&](const std::vector<float>& v) {
    static const float none = 0.f;
    return cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      sizeof(float) * std::max<std::size_t>(1, v.size()), const_cast<float*>(v.empty() ? &none : v.data()));
  };
  const Raster* r = pattern;
  d.raster = upload(r ? r->samples : std::vector<float>());
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
  d.stamp = upload(grey);
  // The label guards: locked classes to the device, the chosen class in the dab.
  const auto* p = std::get_if<PaintSettings>(&stroke.settings);
  const std::vector<int> none{0}, &locked = p && !p->locked_labels.empty() ? p->locked_labels : none;
  d.locked = cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(cl_int) * locked.size(),
                        const_cast<int*>(locked.data()));
  dab.locked_labels = p ? int(p->locked_labels.size()) : 0;
  dab.only_over_label = p ? p->only_over_label : -1;
}

} // namespace meshpaint
