// The painting surface's state (atlas, channel layers, undo log, change
// log) and a stroke's way through the brush pipeline: each dab placed
// (brush_placement.h, brush_space.h), then run by its tool family
// (colour_paint.h, smoothing.h, reshape.h, grab.h, label_edits.h), with the
// tiles it changes remembered first (snapshots.h), and undo and redo.

#include "paint/paint_device.h"

#include "core/errors.h"
#include "core/timer.h"
#include "paint/brush_placement.h"
#include "paint/brush_space.h"
#include "paint/colour_paint.h"
#include "paint/paint_memory.h"
#include "paint/reshape.h"
#include "paint/smoothing.h"
#include "paint/snapshots.h"

#include <algorithm> // for std::any_of, std::find, std::min, std::max
#include <optional>  // for std::optional
#include <limits>    // for std::numeric_limits

namespace meshpaint {

PaintSurface::PaintSurface(std::shared_ptr<Runtime> runtime, const BaseMesh& mesh, int level,
                           AtlasStorage storage, const BaseMaterial& material)
  : atlas_(std::make_unique<Atlas>(runtime, mesh, level, storage)), level_(level),
    device_(std::make_unique<PaintDevice>()), base_material_(material)
{
  check_paint_fits(*atlas_, level, mesh.name);
  atlas_->subdivide(1, level);
  atlas_->compute_limit();
  const LevelLayout l = atlas_->layout(level);
  Runtime& rt = atlas_->runtime();
  PaintDevice& d = *device_;
  try {
    d.positions.build(rt, storage);
    if (storage == AtlasStorage::Buffer)
      d.channels = d.positions;
    else
      d.channels.build(rt, AtlasStorage::Buffer);
    d.brush_cull = cl::Kernel(d.positions.program, "brush_cull");
    d.brush_cull_seed = cl::Kernel(d.positions.program, "brush_cull_seed");
    d.brush_snap = cl::Kernel(d.positions.program, "brush_snap");
    d.brush_reach = cl::Kernel(d.positions.program, "brush_reach");
    d.brush_cull_clusters = cl::Kernel(d.positions.program, "brush_cull_clusters");
    d.brush_reach_clusters = cl::Kernel(d.positions.program, "brush_reach_clusters");
    d.paint_dab = cl::Kernel(d.positions.program, "paint_dab");
    d.paint_patches = cl::Kernel(d.positions.program, "paint_patches");
    d.dab_weights = cl::Kernel(d.positions.program, "dab_weights");
    d.dab_weights_patches = cl::Kernel(d.positions.program, "dab_weights_patches");
    d.move_points = cl::Kernel(d.positions.program, "move_points");
    d.move_points_patches = cl::Kernel(d.positions.program, "move_points_patches");
    d.move_dab = cl::Kernel(d.positions.program, "move_dab");
    d.move_dab_patches = cl::Kernel(d.positions.program, "move_dab_patches");
    d.move_dab_lanes = cl::Kernel(d.positions.program, "move_dab_lanes");
    d.dab_pickup = cl::Kernel(d.positions.program, "dab_pickup");
    d.spray_pick = cl::Kernel(d.positions.program, "spray_pick");
    d.spray_points = cl::Kernel(d.positions.program, "spray_points");
    d.smoothing = std::make_unique<WeldedSmoothing>(rt, atlas_->topology(), d.positions.program);
    const std::size_t bytes = l.texels() * sizeof(Float4);
    d.channel_work = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.weights = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, l.texels() * sizeof(float));
    if (storage == AtlasStorage::Image)
      d.position_work = allocate_layer(rt, l, storage);
    d.diffuse = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.specular = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.material = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    const auto f4 = [](const Float4& v) { return cl_float4{{v[0], v[1], v[2], v[3]}}; };
    rt.queue().enqueueFillBuffer(d.diffuse, f4(material.diffuse), 0, bytes);
    rt.queue().enqueueFillBuffer(d.specular, f4(material.specular), 0, bytes);
    rt.queue().enqueueFillBuffer(d.material, cl_float4{{material.roughness, 0.f, 0.f, 0.f}}, 0, bytes);
    d.counters = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_int2));
    d.open_sides = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, std::size_t(l.patches));
    d.snap_centre = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_float4));
    d.snap_record = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_int));
    d.dab = device_value(rt.context(), BrushDab{});
    d.unfold = device_copy(rt.context(), std::vector<PatchUnfolding>());
    rt.queue().finish();
  } catch (const cl::Error& e) {
    throw DeviceError("cannot set up painting on " + rt.info().name + ": " + describe(e));
  }
  in_stroke_.assign(std::size_t(l.patches), 0);
  changed_at_.assign(std::size_t(l.patches), 0);
  placement_ = BrushPlacement(atlas_->topology());
}

PaintSurface::~PaintSurface() = default;

StrokeReport PaintSurface::apply(const Stroke& stroke) { return apply(stroke, nullptr); }

StrokeReport PaintSurface::apply(const Stroke& stroke, const std::vector<char>& dabs) { return apply(stroke, &dabs); }

StrokeReport PaintSurface::apply(const Stroke& stroke, const std::vector<char>* dabs)
{
  begin_stroke(stroke);
  paint_dabs(stroke_samples(stroke), dabs);
  return end_stroke(stroke);
}

void PaintSurface::close_stroke(const Stroke& stroke)
{
  for (const int p : stroke_before_.patches)
    in_stroke_[std::size_t(p)] = 0;
  if (undo_.recording())
    undo_.record(std::move(stroke_before_));
  stroke_before_ = Snapshot();
  inside_ = false;
  history_.push_back(stroke);
  undone_.clear();
  open_.reset();
}

template <typename F>
void PaintSurface::in_stroke(F&& work)
{
  // A stroke that fails halfway is still one undo step, so that what it
  // changed can be undone, and it enters history() as every stroke does.
  try {
    try {
      work();
    } catch (const cl::Error& e) {
      throw DeviceError("painting failed on " + atlas_->runtime().info().name + ": " + describe(e));
    }
  } catch (...) {
    close_stroke(open_->stroke);
    throw;
  }
}

void PaintSurface::begin_stroke(const Stroke& stroke)
{
  // One undo step per stroke: the tiles its dabs touched, as they were.
  // Every stroke is one step, also one that changed nothing, so that the
  // steps and history() stay in step.
  if (open_)
    throw InputError("a stroke is being drawn already: end it before the next begins");
  check_settings(stroke);
  if (stroke.edit_level() > level_)
    throw InputError("edit_level " + std::to_string(stroke.edit_level()) + " is finer than the surface's level " +
                     std::to_string(level_));
  // Only the layers this tool changes go into its undo step.
  switch (tool_family(stroke)) {
  case ToolFamily::Move:
  case ToolFamily::Smooth: stroke_layers_ = {kPositions}; break;
  case ToolFamily::ColourFilter: stroke_layers_ = {kDiffuse, kSpecular}; break;
  case ToolFamily::Paint:
  case ToolFamily::Label: stroke_layers_ = {kDiffuse, kSpecular, kMaterial}; break;
  }
  // At a coarser edit level, its control points change too.
  const bool coarse = stroke.edit_level() > 0 && stroke.edit_level() < level_ && stroke_layers_.front() == kPositions;
  if (coarse)
    stroke_layers_.push_back(kEditPositions);
  stroke_before_.edit_level = coarse ? stroke.edit_level() : 0;
  stroke_before_.multires = multires_ ? multires_->state() : Multires::State{};
  if (two_sided_ && stroke_layers_.front() != kPositions) // either side may change
    for (const int id : std::vector<int>(stroke_layers_))
      stroke_layers_.push_back(id + kInsideDiffuse - kDiffuse);
  coarse_.begin(std::size_t(atlas_->topology().patch_count));
  phases_ = StepPhases();
  open_ = std::make_unique<OpenStroke>();
  open_->stroke = stroke;
  in_stroke([&] { prepare_dab(stroke); });
}

void PaintSurface::prepare_dab(const Stroke& stroke)
{
  phase_start();
  // Tools without paint of their own take the paint equation's defaults.
  static const PaintSettings no_paint;
  const auto* paints = std::get_if<PaintSettings>(&stroke.settings);
  const PaintSettings& p = paints ? *paints : no_paint;
  BrushDab& dab = open_->dab;
  dab.side_sign = 1.f;
  dab.falloff = stroke.brush.falloff;
  dab.op = p.op;
  for (int c = 0; c < CHANNEL_COUNT; ++c) {
    for (int k = 0; k < 4; ++k)
      dab.value[c][k] = p.value[c][k];
    dab.alpha[c] = p.alpha[c];
  }
  if (p.remover) { // the underlying material, copied back
    const BaseMaterial& m = base_material_;
    for (int k = 0; k < 4; ++k) {
      dab.value[CHANNEL_DIFFUSE][k] = m.diffuse[k];
      dab.value[CHANNEL_SPECULAR][k] = m.specular[k];
      dab.value[CHANNEL_ROUGHNESS][k] = k < 3 ? m.roughness : 1.f;
      dab.value[CHANNEL_DISPLACEMENT][k] = k < 3 ? 0.f : 1.f;
    }
    dab.op = PAINT_OP_COPY;
  }
  dab.specular_coefficient = p.specular_coefficient;
  dab.pattern = p.pattern.kind;
  dab.pattern_coord = p.pattern.coord;
  dab.matte = p.pattern.matte;
  dab.octaves = p.pattern.octaves;
  for (int k = 0; k < 12; ++k)
    dab.pattern_transform[k] = p.pattern.transform[std::size_t(k)];
  if ((p.pattern.kind == PATTERN_IMAGE || p.pattern.kind == PATTERN_VOLUME) &&
      (!p.pattern.raster || p.pattern.raster->empty()))
    throw InputError("the stroke's " + std::string(p.pattern.kind == PATTERN_IMAGE ? "image" : "volume") +
                     " pattern has no samples (load '" + p.pattern.file + "' first)");
  if (!stroke.brush.stamp_file.empty() && (!stroke.brush.stamp || stroke.brush.stamp->empty()))
    throw InputError("the stroke's brush image has no samples (load '" + stroke.brush.stamp_file + "' first)");
  upload_rasters(state(), stroke, dab);
  if (stroke.tool == Tool::Merge) {
    record_labels(merge_labels(state(), p));
    open_->report.dabs = open_->report.dabs_applied = 1;
    return;
  }
  if (covers_everything(stroke.tool)) {
    std::vector<int> all(std::size_t(atlas_->topology().patch_count));
    for (std::size_t p = 0; p < all.size(); ++p)
      all[p] = int(p);
    dab.radius = std::numeric_limits<float>::infinity();
    dab.strength = stroke.brush.strength;
    dab.falloff = FALLOFF_CONSTANT;
    if (stroke.brush.has_camera) // a screen pattern's view
      camera_frame(stroke.brush.camera, dab);
    inside_ = two_sided_ && stroke.brush.side == 2; // a wash covers the outside unless told
    paint_dab(dab_context(), all, dab);
    open_->report.dabs = open_->report.dabs_applied = 1;
    open_->report.patches_touched = all.size();
    return;
  }
  // The mirror plane passes through the centre of the base mesh's bounds.
  const BaseMesh& base = atlas_->base_mesh();
  if (stroke.brush.mirror_axis >= 0) {
    float lo = base.points.front()[stroke.brush.mirror_axis], hi = lo;
    for (const Vec3& p : base.points) {
      lo = std::min(lo, p[stroke.brush.mirror_axis]);
      hi = std::max(hi, p[stroke.brush.mirror_axis]);
    }
    open_->mirror_at = 0.5f * (lo + hi);
  }
}

bool PaintSurface::paint_dabs(const std::vector<DabSample>& samples, const std::vector<char>* dabs)
{
  if (!open_)
    throw InputError("no stroke is being drawn: begin one first");
  OpenStroke& o = *open_;
  if (covers_everything(o.stroke.tool))
    return false;
  in_stroke([&] {
    for (; o.next < samples.size() && !o.ended; ++o.next) {
      const std::size_t index = o.next;
      const bool mine = !dabs || (index < dabs->size() && (*dabs)[index]); // else another object's dab
      if (o.stroke.tool == Tool::Grab) {
        if (!o.grab.step(dab_context(), coarse_, o.stroke, o.dab, samples, index, mine, placer(), o.report))
          o.report.left_surface = o.ended = true;
      } else if (mine)
        paint_sample(samples[index], !dabs);
    }
  });
  return !o.ended;
}

void PaintSurface::paint_sample(const DabSample& sample, bool may_end)
{
  OpenStroke& o = *open_;
  const Stroke& stroke = o.stroke;
  BrushDab& dab = o.dab;
  // The dab, and with a mirror its reflection (heading reflected too).
  std::vector<DabSample> dabs{sample};
  if (stroke.brush.mirror_axis >= 0) {
    DabSample m = sample;
    m.centre[stroke.brush.mirror_axis] = 2.f * o.mirror_at - m.centre[stroke.brush.mirror_axis];
    m.heading[stroke.brush.mirror_axis] = -m.heading[stroke.brush.mirror_axis];
    dabs.push_back(m);
  }
  dab.radius = stroke.brush.radius * sample.pressure;
  dab.strength = stroke.brush.strength * sample.pressure;
  bool on_surface = false;
  if (stroke.tool == Tool::Fill) { // no brush: the region around one point
    ++o.report.dabs;
    CullRecord seed{};
    on_surface = dab.radius > 0.f && !brush_patches(sample.centre, dab.radius, nullptr, nullptr, 0.f, &seed).empty();
    if (on_surface)
      record_labels(fill_labels(state(), seed, stroke.paint()));
    o.report.dabs_applied += on_surface ? 1 : 0;
    dabs.clear();
  }
  for (std::size_t side = 0; side < dabs.size(); ++side) {
    ++o.report.dabs;
    if (!(dab.radius > 0.f))
      continue;
    Vec3 normal;
    phase_start();
    const std::vector<int> patches = place(stroke, dabs[side], dab, normal);
    phase_done(&StepPhases::place);
    if (patches.empty())
      continue;
    on_surface = true;
    const DabContext context = dab_context();
    if (stroke.tool == Tool::Smear)
      smear_dab(context, patches, dab, o.carried[side]);
    else if (const auto* p = std::get_if<PaintSettings>(&stroke.settings); p && p->spray_drops > 0)
      spray_dab(context, patches, dab, stroke, o.report.dabs, placer());
    else if (stroke.tool == Tool::Paint || stroke.tool == Tool::Label)
      paint_dab(context, patches, dab);
    else
      reshape_dab(context, coarse_, patches, dab, stroke, normal);
    ++o.report.dabs_applied;
    o.report.patches_touched += patches.size();
  }
  // Zero pressure skips a dab, no surface ends the stroke (in a scene, the
  // scene decides that).
  if (!on_surface && dab.radius > 0.f && may_end) {
    o.report.left_surface = true;
    o.ended = true;
  }
}

void PaintSurface::record_labels(LabelEdit edit)
{
  if (edit.texels.empty())
    return;
  remember(edit.patches);
  write_labels(state(), edit);
}

PlaceDab PaintSurface::placer()
{
  return [this](const Stroke& stroke, const DabSample& sample, BrushDab& dab, Vec3& normal) {
    return place(stroke, sample, dab, normal);
  };
}

std::vector<int> PaintSurface::place(const Stroke& stroke, const DabSample& sample, BrushDab& dab, Vec3& normal)
{
  // A tangent or screen footprint runs further than the radius in space on
  // surface turned from the brush: the search for it goes that far, at most.
  const float reach =
    dab.radius * (stroke.brush.space == SPACE_SCREEN ? 4.f : stroke.brush.space == SPACE_OBJECT ? 1.f : 2.f);
  Vec3 centre;
  CullRecord closest{};
  std::vector<int> patches = placement_.brush_patches(state(), sample.centre, dab.radius, &centre, &normal, reach,
                                                        &closest);
  if (patches.empty())
    return patches;
  for (int k = 0; k < 3; ++k)
    dab.centre[k] = centre[k];
  dab.unfolded = 0;
  choose_side(stroke, sample.centre, normal, dab);
  if (!aim(state(), stroke.brush, normal, sample.heading, closest, dab))
    return {};
  if (stroke.brush.space == SPACE_PARAMETER)
    return unfold_dab(state(), closest.patch, dab);
  return patches;
}

void PaintSurface::choose_side(const Stroke& stroke, const Vec3& point, const Vec3& normal, BrushDab& dab)
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
}

StrokeReport PaintSurface::end_stroke(const Stroke& stroke)
{
  if (!open_)
    throw InputError("no stroke is being drawn: begin one first");
  open_->stroke = stroke; // the whole path: what history() and replays hold
  StrokeReport report;
  in_stroke([&] {
    if (stroke.tool == Tool::Grab)
      open_->grab.end(dab_context(), coarse_, stroke, open_->dab, open_->report);
    report = open_->report;
    report.stretch = coarse_.stretch(dab_context());
    report.encode_ms = coarse_.encode_ms();
    report.phases = phases_;
    atlas_->finish(); // the stroke's time holds all of its device work
  });
  report.ms = open_->timer.ms();
  close_stroke(stroke);
  return report;
}

std::vector<int> PaintSurface::brush_patches(const Vec3& point, float radius, Vec3* centre, Vec3* centre_normal,
                                             float reach, CullRecord* closest)
{
  return placement_.brush_patches(state(), point, radius, centre, centre_normal, reach, closest);
}

void PaintSurface::hint_snap(int patch, double u, double v) { placement_.hint_snap(state(), patch, u, v); }

float PaintSurface::distance_to(const Vec3& point, float radius)
{
  return placement_.distance_to(state(), point, radius);
}

void PaintSurface::phase_start()
{
  if (time_phases_) {
    atlas_->runtime().queue().finish();
    phase_clock_.restart();
  }
}

void PaintSurface::phase_done(double StepPhases::*phase)
{
  if (!time_phases_)
    return;
  atlas_->runtime().queue().finish();
  phases_.*phase += phase_clock_.ms();
  phase_clock_.restart();
}

void PaintSurface::geometry_changed()
{
  changed_all();
  if (multires_)
    multires_->invalidate();
  atlas_->compute_limit(); // and the bounds
  atlas_->finish();
}

PaintChannels PaintSurface::read_channels()
{
  const std::size_t n = atlas_->layout(level_).texels();
  PaintChannels c;
  c.diffuse.resize(n);
  c.specular.resize(n);
  c.material.resize(n);
  cl::CommandQueue& q = atlas_->runtime().queue();
  q.enqueueReadBuffer(device_->diffuse, CL_TRUE, 0, n * sizeof(Float4), c.diffuse.data());
  q.enqueueReadBuffer(device_->specular, CL_TRUE, 0, n * sizeof(Float4), c.specular.data());
  q.enqueueReadBuffer(device_->material, CL_TRUE, 0, n * sizeof(Float4), c.material.data());
  if (two_sided_) {
    for (auto [from, to] : {std::pair{&device_->inside_diffuse, &c.inside_diffuse},
                            std::pair{&device_->inside_specular, &c.inside_specular},
                            std::pair{&device_->inside_material, &c.inside_material}}) {
      to->resize(n);
      q.enqueueReadBuffer(*from, CL_TRUE, 0, n * sizeof(Float4), to->data());
    }
  }
  return c;
}

void PaintSurface::set_two_sided(bool on)
{
  if (on == two_sided_)
    return;
  display_ = nullptr; // made again with (or without) the inside's arrays
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const std::size_t bytes = atlas_->layout(level_).texels() * sizeof(Float4);
  if (on) {
    try {
      d.inside_diffuse = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
      d.inside_specular = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
      d.inside_material = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
      const auto f4 = [](const Float4& v) { return cl_float4{{v[0], v[1], v[2], v[3]}}; };
      rt.queue().enqueueFillBuffer(d.inside_diffuse, f4(base_material_.diffuse), 0, bytes);
      rt.queue().enqueueFillBuffer(d.inside_specular, f4(base_material_.specular), 0, bytes);
      rt.queue().enqueueFillBuffer(d.inside_material, cl_float4{{base_material_.roughness, 0.f, 0.f, 0.f}}, 0, bytes);
      rt.queue().finish();
    } catch (const cl::Error& e) {
      throw DeviceError("cannot add the inside channels on " + rt.info().name + ": " + describe(e));
    }
  } else {
    d.inside_diffuse = d.inside_specular = d.inside_material = cl::Buffer();
  }
  two_sided_ = on;
  changed_all();
  // Steps recorded for the other number of layers cannot be undone.
  UndoLog fresh(undo_.budget());
  fresh.set_recording(undo_.recording());
  undo_ = std::move(fresh);
}

void PaintSurface::write_channels(const PaintChannels& c)
{
  changed_all();
  const std::size_t n = atlas_->layout(level_).texels();
  if (c.diffuse.size() != n || c.specular.size() != n || c.material.size() != n)
    throw InputError("channel layers of " + std::to_string(c.diffuse.size()) + " texels do not fit a level-" +
                     std::to_string(level_) + " atlas of " + std::to_string(n));
  cl::CommandQueue& q = atlas_->runtime().queue();
  q.enqueueWriteBuffer(device_->diffuse, CL_TRUE, 0, n * sizeof(Float4), c.diffuse.data());
  q.enqueueWriteBuffer(device_->specular, CL_TRUE, 0, n * sizeof(Float4), c.specular.data());
  q.enqueueWriteBuffer(device_->material, CL_TRUE, 0, n * sizeof(Float4), c.material.data());
  const auto masks = [](const std::vector<Float4>& material) {
    return std::any_of(material.begin(), material.end(), [](const Float4& m) { return m[3] != 0.f; });
  };
  mask_painted_ = masks(c.material) || masks(c.inside_material);
  if (c.inside_diffuse.empty())
    return;
  if (c.inside_diffuse.size() != n || c.inside_specular.size() != n || c.inside_material.size() != n)
    throw InputError("inside channel layers of " + std::to_string(c.inside_diffuse.size()) +
                     " texels do not fit a level-" + std::to_string(level_) + " atlas of " + std::to_string(n));
  set_two_sided(true);
  q.enqueueWriteBuffer(device_->inside_diffuse, CL_TRUE, 0, n * sizeof(Float4), c.inside_diffuse.data());
  q.enqueueWriteBuffer(device_->inside_specular, CL_TRUE, 0, n * sizeof(Float4), c.inside_specular.data());
  q.enqueueWriteBuffer(device_->inside_material, CL_TRUE, 0, n * sizeof(Float4), c.inside_material.data());
}

void PaintSurface::restore(const Snapshot& s)
{
  for (const int id : s.layer_ids) // the tiles put back may carry a mask
    mask_painted_ = mask_painted_ || id == kMaterial || id == kInsideMaterial;
  Runtime& rt = atlas_->runtime();
  const cl::Buffer list = s.patches.empty() ? cl::Buffer() : device_ints(rt.context(), s.patches);
  const PaintState st = state();
  const auto scatter = [&](std::size_t k) { put_back_layer(st, s, k, list); };
  const auto edit = std::find(s.layer_ids.begin(), s.layer_ids.end(), int(kEditPositions));
  if (!s.patches.empty() && edit != s.layer_ids.end()) {
    // The edit level's control points, and the levels up to the finest made
    // from them, which the next edit at that level reads around its reach.
    scatter(std::size_t(edit - s.layer_ids.begin()));
    if (s.edit_level + 1 < level_) {
      atlas_->subdivide(s.edit_level, level_ - 1, atlas_->neighbourhood(s.patches));
    }
  }
  // Then the details, before the finest level, which they leave alone.
  if (multires_) {
    if (s.memo)
      multires_->load(*s.memo);
    multires_->resume(s.multires);
  }
  if (s.patches.empty())
    return;
  changed(s.patches);
  for (std::size_t k = 0; k < s.layer_ids.size(); ++k)
    if (s.layer_ids[k] != kEditPositions)
      scatter(k);
  if (std::find(s.layer_ids.begin(), s.layer_ids.end(), int(kPositions)) != s.layer_ids.end())
    refresh_geometry(dab_context(), s.patches);
  rt.queue().finish();
}

void PaintSurface::remember(const std::vector<int>& patches)
{
  changed(patches); // every dab that changes tiles says which here, first
  if (!undo_.recording())
    return;
  std::vector<int> fresh;
  for (const int p : patches)
    if (!in_stroke_[std::size_t(p)])
      fresh.push_back(p);
  if (fresh.empty())
    return;
  Snapshot s = take_snapshot(state(), fresh, stroke_layers_, stroke_before_.edit_level); // flags only once the tiles are safe
  for (const int p : fresh)
    in_stroke_[std::size_t(p)] = 1;
  stroke_before_.layer_ids = s.layer_ids;
  stroke_before_.patches.insert(stroke_before_.patches.end(), s.patches.begin(), s.patches.end());
  stroke_before_.layers.resize(std::max(stroke_before_.layers.size(), s.layers.size()));
  for (std::size_t k = 0; k < s.layers.size(); ++k)
    stroke_before_.layers[k].insert(stroke_before_.layers[k].end(), s.layers[k].begin(), s.layers[k].end());
}

void PaintSurface::remember_details()
{
  if (undo_.recording() && multires_->encoded_level() >= 0 && !stroke_before_.memo)
    stroke_before_.memo = std::make_shared<const Multires::Memo>(multires_->save());
}

bool PaintSurface::undo()
{
  if (!step(true))
    return false;
  undone_.push_back(std::move(history_.back()));
  history_.pop_back();
  return true;
}

bool PaintSurface::take_back()
{
  if (!undo_.recording() || !undo())
    return false;
  undone_.pop_back();
  undo_.forget_redo(); // the newest stroke was the last: nothing else could be redone
  return true;
}

bool PaintSurface::redo()
{
  if (!step(false))
    return false;
  history_.push_back(std::move(undone_.back()));
  undone_.pop_back();
  return true;
}

bool PaintSurface::step(bool back)
{
  if (back ? !undo_.can_undo() : !undo_.can_redo())
    return false;
  // Keep the present state of the same tiles, so the step can be reversed.
  const Snapshot& target = back ? undo_.next_undo() : undo_.next_redo();
  Snapshot now = take_snapshot(state(), target.patches, target.layer_ids, target.edit_level);
  if (target.memo && multires_) // the step puts back another encoding: keep this one for the way back
    now.memo = std::make_shared<const Multires::Memo>(multires_->save());
  restore(target);
  if (back)
    undo_.undone(std::move(now));
  else
    undo_.redone(std::move(now));
  return true;
}

} // namespace meshpaint
