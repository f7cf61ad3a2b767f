#include "paint/paint_surface.h"

#include "atlas/weld.h"
#include "cl/launch.h"
#include "cl/program.h"
#include "core/errors.h"
#include "core/timer.h"

#include <algorithm> // for std::sort, std::max
#include <cmath>     // for std::sqrt
#include <limits>    // for std::numeric_limits
#include <unordered_map> // for std::unordered_map

namespace meshpaint {
namespace {

constexpr std::size_t kGroup = 64;

} // namespace

struct PaintSurface::Cull
{
  CullRecord record;
};

//! Device state of the brush pipeline.
struct PaintSurface::Device
{
  cl::Program program;
  cl::Kernel patch_bounds, brush_cull, paint_dab, gather_tiles, scatter_tiles;
  cl::Buffer bounds, records, count, active, dab;
  std::size_t record_capacity = 0, active_capacity = 0;
  cl::Buffer diffuse, specular, material;
};

PaintSurface::PaintSurface(std::shared_ptr<Runtime> runtime, const BaseMesh& mesh, int level,
                           AtlasStorage storage, const BaseMaterial& material)
  : atlas_(std::make_unique<Atlas>(runtime, mesh, level, storage)), level_(level), device_(std::make_unique<Device>())
{
  atlas_->subdivide(1, level);
  positions_ = atlas_->read_limit_positions();
  const LevelLayout l = atlas_->layout(level);
  Runtime& rt = atlas_->runtime();
  Device& d = *device_;
  try {
    d.program = build_program(rt, std::vector<std::string>{"atlas_types.h", "atlas_access.cl", "brush.cl"},
                              std::string("-cl-std=CL1.2") + (storage == AtlasStorage::Image ? " -D ATLAS_IMAGE" : ""));
    d.patch_bounds = cl::Kernel(d.program, "patch_bounds");
    d.brush_cull = cl::Kernel(d.program, "brush_cull");
    d.paint_dab = cl::Kernel(d.program, "paint_dab");
    d.gather_tiles = cl::Kernel(d.program, "gather_tiles");
    d.scatter_tiles = cl::Kernel(d.program, "scatter_tiles");
    const std::size_t bytes = l.texels() * sizeof(Float4);
    d.diffuse = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.specular = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    d.material = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, bytes);
    const auto f4 = [](const Float4& v) { return cl_float4{{v[0], v[1], v[2], v[3]}}; };
    rt.queue().enqueueFillBuffer(d.diffuse, f4(material.diffuse), 0, bytes);
    rt.queue().enqueueFillBuffer(d.specular, f4(material.specular), 0, bytes);
    rt.queue().enqueueFillBuffer(d.material, cl_float4{{material.roughness, 0.f, 0.f, 0.f}}, 0, bytes);
    d.bounds = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_float4) * l.patches);
    d.count = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_int));
    d.dab = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(BrushDab));
    launch(rt.queue(), d.patch_bounds, cl::NDRange(round_up(l.patches, kGroup)), cl::NDRange(kGroup),
           atlas_->limit_positions_layer(), grid(l), l.patches, d.bounds);
    rt.queue().finish();
  } catch (const cl::Error& e) {
    throw DeviceError("cannot set up painting on " + rt.info().name + ": " + describe(e));
  }
  in_stroke_.assign(std::size_t(l.patches), 0);
}

Snapshot PaintSurface::take_snapshot(const std::vector<int>& patches)
{
  Snapshot s;
  s.patches = patches;
  if (patches.empty())
    return s;
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  const std::size_t tile_texels = std::size_t(l.tile) * l.tile, n = patches.size() * tile_texels;
  cl::Buffer list(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(int) * patches.size(),
                  const_cast<int*>(patches.data()));
  cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(Float4) * n);
  for (const cl::Buffer* layer : {&d.diffuse, &d.specular, &d.material}) {
    launch(rt.queue(), d.gather_tiles, cl::NDRange(round_up(tile_texels, 8), patches.size()), cl::NullRange, *layer,
           list, cl_int(patches.size()), cl_int(tile_texels), out, cl_int(0));
    s.layers.emplace_back(n);
    rt.queue().enqueueReadBuffer(out, CL_TRUE, 0, sizeof(Float4) * n, s.layers.back().data());
  }
  return s;
}

void PaintSurface::restore(const Snapshot& s)
{
  if (s.patches.empty())
    return;
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  const std::size_t tile_texels = std::size_t(l.tile) * l.tile, n = s.patches.size() * tile_texels;
  cl::Buffer list(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(int) * s.patches.size(),
                  const_cast<int*>(s.patches.data()));
  const cl::Buffer* layers[] = {&d.diffuse, &d.specular, &d.material};
  for (std::size_t k = 0; k < 3; ++k) {
    cl::Buffer in(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(Float4) * n,
                  const_cast<Float4*>(s.layers[k].data()));
    launch(rt.queue(), d.scatter_tiles, cl::NDRange(round_up(tile_texels, 8), s.patches.size()), cl::NullRange,
           *layers[k], list, cl_int(s.patches.size()), cl_int(tile_texels), in, cl_int(0));
    rt.queue().finish();
  }
}

void PaintSurface::remember(const std::vector<int>& patches)
{
  std::vector<int> fresh;
  for (const int p : patches)
    if (!in_stroke_[std::size_t(p)]) {
      in_stroke_[std::size_t(p)] = 1;
      fresh.push_back(p);
    }
  if (fresh.empty())
    return;
  Snapshot s = take_snapshot(fresh);
  stroke_before_.patches.insert(stroke_before_.patches.end(), s.patches.begin(), s.patches.end());
  stroke_before_.layers.resize(std::max(stroke_before_.layers.size(), s.layers.size()));
  for (std::size_t k = 0; k < s.layers.size(); ++k)
    stroke_before_.layers[k].insert(stroke_before_.layers[k].end(), s.layers[k].begin(), s.layers[k].end());
}

bool PaintSurface::undo()
{
  if (!undo_.can_undo())
    return false;
  const Snapshot& before = undo_.next_undo();
  Snapshot now = take_snapshot(before.patches);
  restore(before);
  undo_.undone(std::move(now));
  return true;
}

bool PaintSurface::redo()
{
  if (!undo_.can_redo())
    return false;
  const Snapshot& after = undo_.next_redo();
  Snapshot now = take_snapshot(after.patches);
  restore(after);
  undo_.redone(std::move(now));
  return true;
}

PaintSurface::~PaintSurface() = default;

std::vector<PaintSurface::Cull> PaintSurface::cull(const Vec3& centre, float radius)
{
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  const cl_float4 c{{centre[0], centre[1], centre[2], 0.f}};
  cl_int count = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (d.record_capacity == 0) {
      d.record_capacity = std::min<std::size_t>(std::max(l.patches, 1), 4096);
      d.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(CullRecord) * d.record_capacity);
    }
    count = 0;
    rt.queue().enqueueWriteBuffer(d.count, CL_FALSE, 0, sizeof count, &count);
    launch(rt.queue(), d.brush_cull, cl::NDRange(round_up(l.patches, kGroup)), cl::NDRange(kGroup),
           atlas_->limit_positions_layer(), grid(l), l.patches, d.bounds, c, radius, d.records, d.count,
           cl_int(d.record_capacity));
    rt.queue().enqueueReadBuffer(d.count, CL_TRUE, 0, sizeof count, &count);
    if (std::size_t(count) <= d.record_capacity)
      break;
    d.record_capacity = std::size_t(count); // grow and run once more
    d.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(CullRecord) * d.record_capacity);
  }
  std::vector<Cull> out(static_cast<std::size_t>(count));
  if (count > 0)
    rt.queue().enqueueReadBuffer(d.records, CL_TRUE, 0, sizeof(CullRecord) * count, out.data());
  // Appends land in any order; sort so that everything after is deterministic.
  std::sort(out.begin(), out.end(), [](const Cull& a, const Cull& b) { return a.record.patch < b.record.patch; });
  return out;
}

std::vector<int> PaintSurface::brush_patches(const Vec3& point, float radius, Vec3* centre_out)
{
  // Snap: the closest texel within the radius is the brush centre.
  const std::vector<Cull> near = cull(point, radius);
  if (near.empty())
    return {};
  const Cull* best = &near.front();
  for (const Cull& c : near)
    if (c.record.distance < best->record.distance)
      best = &c;
  const LevelLayout l = atlas_->layout(level_);
  const Float4& snapped = positions_[std::size_t(best->record.patch) * l.tile * l.tile + best->record.closest_texel];
  const Vec3 centre{snapped[0], snapped[1], snapped[2]};
  if (centre_out)
    *centre_out = centre;

  // The brush reaches the patches connected to the centre's patch through
  // sides that themselves come within the radius: never through the air.
  const std::vector<Cull> reach = cull(centre, radius);
  std::unordered_map<int, const CullRecord*> by_patch;
  for (const Cull& c : reach)
    by_patch[c.record.patch] = &c.record;
  const AtlasTopology& topo = atlas_->topology();
  std::vector<int> active, stack{best->record.patch};
  std::unordered_map<int, bool> seen{{best->record.patch, true}};
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    const auto it = by_patch.find(p);
    if (it == by_patch.end())
      continue;
    active.push_back(p);
    for (int s = 0; s < 4; ++s) {
      if (!(it->second->side_distance[s] <= radius))
        continue;
      const PatchEdge& e = topo.edges[topo.patch_sides[p][s]];
      const int q = e.patch[0] == p && e.side[0] == s ? e.patch[1] : e.patch[0];
      if (q >= 0 && !seen[q]) {
        seen[q] = true;
        stack.push_back(q);
      }
    }
  }
  std::sort(active.begin(), active.end());
  return active;
}

void PaintSurface::paint(const std::vector<int>& patches, const BrushDab& dab)
{
  if (patches.empty())
    return;
  remember(patches);
  Device& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout l = atlas_->layout(level_);
  if (d.active_capacity < patches.size()) {
    d.active_capacity = std::max(patches.size(), std::size_t(l.patches < 1024 ? l.patches : 1024));
    d.active = cl::Buffer(rt.context(), CL_MEM_READ_ONLY, sizeof(cl_int) * d.active_capacity);
  }
  rt.queue().enqueueWriteBuffer(d.active, CL_FALSE, 0, sizeof(cl_int) * patches.size(), patches.data());
  rt.queue().enqueueWriteBuffer(d.dab, CL_FALSE, 0, sizeof dab, &dab);
  const std::size_t rows = std::max<std::size_t>(1, 256 / std::size_t(l.tile));
  launch(rt.queue(), d.paint_dab,
         cl::NDRange(std::size_t(l.tile), round_up(std::size_t(l.tile) * patches.size(), rows)),
         cl::NDRange(std::size_t(l.tile), rows), atlas_->limit_positions_layer(), grid(l), d.active,
         cl_int(patches.size()), d.dab, d.diffuse, d.specular, d.material);
  // The host buffers above must outlive the copies: wait for this dab.
  rt.queue().finish();
}

StrokeReport PaintSurface::apply(const Stroke& stroke)
{
  // One undo step per stroke: the tiles its dabs touched, as they were; also
  // when a dab fails halfway, so that what it changed can be undone.
  const auto finish_stroke = [this] {
    for (const int p : stroke_before_.patches)
      in_stroke_[std::size_t(p)] = 0;
    if (!stroke_before_.patches.empty())
      undo_.record(std::move(stroke_before_));
    stroke_before_ = Snapshot();
  };
  StrokeReport report;
  try {
    report = apply_dabs(stroke);
  } catch (...) {
    finish_stroke();
    throw;
  }
  finish_stroke();
  return report;
}

StrokeReport PaintSurface::apply_dabs(const Stroke& stroke)
{
  Timer timer;
  StrokeReport report;
  BrushDab dab{};
  dab.falloff = stroke.falloff;
  dab.op = stroke.op;
  for (int c = 0; c < CHANNEL_COUNT; ++c) {
    for (int k = 0; k < 4; ++k)
      dab.value[c][k] = stroke.value[c][k];
    dab.alpha[c] = stroke.alpha[c];
  }
  try {
    if (stroke.tool == Tool::Wash) {
      std::vector<int> all(std::size_t(atlas_->topology().patch_count));
      for (std::size_t p = 0; p < all.size(); ++p)
        all[p] = int(p);
      dab.radius = std::numeric_limits<float>::infinity();
      dab.strength = stroke.strength;
      dab.falloff = FALLOFF_CONSTANT;
      paint(all, dab);
      report.dabs = report.dabs_applied = 1;
      report.patches_touched = all.size();
      report.ms = timer.ms();
      return report;
    }
    // The mirror plane passes through the centre of the base mesh's bounds.
    const BaseMesh& base = atlas_->base_mesh();
    float mirror_at = 0.f;
    if (stroke.mirror_axis >= 0) {
      float lo = base.points.front()[stroke.mirror_axis], hi = lo;
      for (const Vec3& p : base.points) {
        lo = std::min(lo, p[stroke.mirror_axis]);
        hi = std::max(hi, p[stroke.mirror_axis]);
      }
      mirror_at = 0.5f * (lo + hi);
    }
    for (const DabSample& sample : stroke_samples(stroke)) {
      std::vector<Vec3> centres{sample.centre};
      if (stroke.mirror_axis >= 0) {
        Vec3 m = sample.centre;
        m[stroke.mirror_axis] = 2.f * mirror_at - m[stroke.mirror_axis];
        centres.push_back(m);
      }
      dab.radius = stroke.radius * sample.pressure;
      dab.strength = stroke.strength * sample.pressure;
      bool on_surface = false;
      for (const Vec3& point : centres) {
        ++report.dabs;
        if (!(dab.radius > 0.f))
          continue;
        Vec3 centre;
        const std::vector<int> patches = brush_patches(point, dab.radius, &centre);
        if (patches.empty())
          continue;
        on_surface = true;
        dab.centre[0] = centre[0];
        dab.centre[1] = centre[1];
        dab.centre[2] = centre[2];
        paint(patches, dab);
        ++report.dabs_applied;
        report.patches_touched += patches.size();
      }
      if (!on_surface && dab.radius > 0.f) { // zero pressure skips a dab, no surface ends the stroke
        report.left_surface = true;
        break;
      }
    }
  } catch (const cl::Error& e) {
    throw DeviceError("painting failed on " + atlas_->runtime().info().name + ": " + describe(e));
  }
  report.ms = timer.ms();
  return report;
}

PaintChannels PaintSurface::read_channels()
{
  const std::size_t n = atlas_->layout(level_).texels();
  PaintChannels c{std::vector<Float4>(n), std::vector<Float4>(n), std::vector<Float4>(n)};
  cl::CommandQueue& q = atlas_->runtime().queue();
  q.enqueueReadBuffer(device_->diffuse, CL_TRUE, 0, n * sizeof(Float4), c.diffuse.data());
  q.enqueueReadBuffer(device_->specular, CL_TRUE, 0, n * sizeof(Float4), c.specular.data());
  q.enqueueReadBuffer(device_->material, CL_TRUE, 0, n * sizeof(Float4), c.material.data());
  return c;
}

PaintedSurface PaintSurface::painted_surface()
{
  PaintedSurface out;
  out.surface = level_surface(*atlas_, level_, true);
  const PaintChannels c = read_channels();
  const std::vector<int> map = weld_map(atlas_->topology(), atlas_->layout(level_));
  const std::size_t nv = out.surface.points.size();
  out.diffuse.resize(nv);
  out.specular.resize(nv);
  out.roughness.resize(nv);
  out.displacement.resize(nv);
  out.mask.resize(nv);
  out.label.resize(nv);
  for (std::size_t t = 0; t < map.size(); ++t) {
    const int v = map[t];
    out.diffuse[v] = {c.diffuse[t][0], c.diffuse[t][1], c.diffuse[t][2]};
    out.specular[v] = {c.specular[t][0], c.specular[t][1], c.specular[t][2]};
    out.roughness[v] = c.material[t][0];
    out.displacement[v] = c.material[t][1];
    out.label[v] = int(c.material[t][2]);
    out.mask[v] = c.material[t][3];
  }
  for (std::size_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k)
      out.surface.points[v][k] += out.displacement[v] * out.surface.normals[v][k];
  return out;
}

} // namespace meshpaint
