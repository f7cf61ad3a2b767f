// Geometry brushes: the dab's weights, then smoothing (positions or colours)
// or a move (sculpt, inflate, flatten, grab) at the painting level, or at a
// coarser edit level with the finer levels rebuilt from their details
// (multiresolution editing); then the limit surface where it changed.

#include "paint/paint_device.h"

#include "core/timer.h"

#include <algorithm> // for std::max

namespace meshpaint {

void PaintSurface::weigh(const std::vector<int>& patches, const cl::Buffer& list, const BrushDab& dab, int level)
{
  // At a coarser edit level, on the limit of that level's control points.
  // The patches come from the finest surface, so that level's weights may
  // reach the sides they share with other patches: those stay put.
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  const LevelLayout f = atlas_->layout(level_), l = atlas_->layout(level);
  const bool coarse = level < level_;
  const int stride = f.n / l.n;
  // The outside bits first: the blocking write below waits for the kernels
  // queued before it (a coarse edit's limit), which run meanwhile.
  cl::Buffer outside;
  if (coarse) {
    std::vector<std::uint8_t> bits = atlas_->shared_outside(patches);
    bits.resize(std::max<std::size_t>(1, bits.size())); // a valid argument when empty
    outside = cl::Buffer(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bits.size(), bits.data());
  }
  BrushDab at_level = dab; // parameter space counts texels of the level
  for (float& c : at_level.centre_texel)
    c /= float(stride);
  at_level.texel_size *= float(stride);
  rt.queue().enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof at_level, &at_level);
  const int count = int(patches.size());
  const auto tiles = range_tiles(l, count);
  launch(rt.queue(), d.dab_weights, tiles.first, tiles.second,
         coarse ? multires_->base_positions() : atlas_->limit_positions_layer(),
         coarse ? multires_->base_normals() : atlas_->limit_normals_layer(), grid(l), list, count, d.dab, d.unfold,
         d.stamp, material_buffer(), cl_int(mask_painted_), grid(f), stride, outside,
         coarse ? multires_->base_weights() : d.weights);
}

void PaintSurface::reshape(const std::vector<int>& patches, const BrushDab& dab, const Stroke& stroke,
                           const Vec3& normal, bool reweigh)
{
  // At a coarser edit level the brush moves that level's control points and
  // the finest level is rebuilt with its details (Multires); the finest
  // patches that may change are then more than the brush's.
  const int level = stroke.edit_level() > 0 ? stroke.edit_level() : level_;
  const bool coarse = level < level_;
  std::vector<int> changed;
  if (coarse) {
    if (!multires_)
      multires_ = std::make_unique<Multires>(*atlas_);
    // Details persist across strokes at the same level; a stroke at the
    // finest level or at another level has them made again. Undo puts back
    // the encoding a step replaced, so a replay of what remains applied
    // encodes exactly where the session did.
    if (multires_->level() != level) {
      if (undo_.recording() && multires_->encoded_level() >= 0 && !stroke_before_.memo)
        stroke_before_.memo = std::make_shared<const Multires::Memo>(multires_->save());
      atlas_->runtime().queue().finish(); // the encoding timed alone
      const Timer encoding;
      multires_->encode(level);
      atlas_->runtime().queue().finish();
      encode_ms_ += encoding.ms();
    }
    // The edit level's limit, which the weights stand on, is computed on
    // the device while the host works out what the edit reaches (and, in
    // weigh(), which sides it shares): neither waits for the other.
    phase_done(&StepPhases::record); // the encoding, if any
    if (reweigh) {
      multires_->compute_base_limit(patches);
      phase_done(&StepPhases::weights);
    }
    changed = multires_->reach(patches);
  } else if (tool_family(stroke) != ToolFamily::ColourFilter && multires_) {
    multires_->detach();
  }
  remember(coarse ? changed : patches);
  phase_done(&StepPhases::record);
  PaintDevice& d = *device_;
  Runtime& rt = atlas_->runtime();
  cl::CommandQueue& q = rt.queue();
  const LevelLayout l = atlas_->layout(level);
  const int count = int(patches.size());
  const cl::Buffer list = device_ints(rt.context(), patches);
  const auto tiles = range_tiles(l, count);
  const bool moves = tool_family(stroke) == ToolFamily::Move;
  // A move at the painting level weighs as it moves (move_dab); the
  // weights are kept only where something reads them again: a grab's later
  // dabs, smoothing passes, a coarse edit.
  const bool weigh_as_moved = moves && !coarse && stroke.tool != Tool::Grab;
  if (reweigh && !weigh_as_moved)
    weigh(patches, list, dab, level);
  phase_done(&StepPhases::weights);
  const cl::Buffer& weights = coarse ? multires_->base_weights() : d.weights;
  const auto geometry_done = [&] {
    if (!coarse) {
      refresh_geometry(patches, &list);
      return;
    }
    const PatchSet around = atlas_->neighbourhood(changed);
    phase_done(&StepPhases::lists);
    multires_->reconstruct(changed, around);
    for (const int p : changed)
      if (stretched_marks_.mark(std::size_t(p)))
        stretched_.push_back(p);
    phase_done(&StepPhases::rebuild);
    refresh_geometry(around);
  };

  if (moves) {
    // A grab moves by the path's step (`normal`) times the weight.
    const int mode = stroke.tool == Tool::Inflate ? MOVE_INFLATE : stroke.tool == Tool::Flatten ? MOVE_FLATTEN
                                                                                                 : MOVE_SCULPT;
    const float amount = stroke.tool == Tool::Grab ? 1.f : stroke.move().amount;
    const cl::Memory& pos = atlas_->level_layer(level);
    const bool in_place = atlas_->storage() == AtlasStorage::Buffer; // see geometry.cl
    const cl::Memory& moved = in_place ? pos : d.position_work;
    const cl::Memory& normals = coarse ? multires_->base_normals() : atlas_->limit_normals_layer();
    const cl_float4 centre{{dab.centre[0], dab.centre[1], dab.centre[2], 0.f}};
    const cl_float4 towards{{normal[0], normal[1], normal[2], 0.f}};
    if (weigh_as_moved) {
      const bool plain = dab.space == SPACE_OBJECT && dab.stamp_size[0] == 0 && !mask_painted_;
      q.enqueueWriteBuffer(d.dab, CL_TRUE, 0, sizeof dab, &dab);
      const Atlas::TileLaunch t = atlas_->tile_launch(d.move_dab, d.move_dab_patches, l, count);
      launch(q, t.kernel, t.global, t.local, pos, moved, atlas_->limit_positions_layer(), normals, grid(l), list,
             count, d.dab, d.unfold, d.stamp, material_buffer(), cl_int(mask_painted_), mode, amount, centre, towards,
             cl_int(plain), dab.radius, cl_int(dab.falloff), dab.strength);
    } else {
      launch(q, d.move_points, tiles.first, tiles.second, pos, moved, normals, grid(l), list, count,
             weights, mode, amount, centre, towards);
    }
    if (!in_place)
      launch(q, d.positions.copy_tiles, tiles.first, tiles.second, d.position_work, pos, grid(l), list, count);
    phase_done(&StepPhases::transform);
    geometry_done();
    return;
  }

  // Smoothing: of the control points, or of the colour channels. Edges and
  // corners are smoothed only where every patch sharing them is in the
  // brush; elsewhere their weight is zero anyway.
  const bool everything = count == l.patches;
  const PatchSet set = everything ? PatchSet() : atlas_->patch_set(patches, Reach::All);
  std::vector<std::pair<LayerKernels*, const cl::Memory*>> layers;
  if (stroke.smooth().target_colour)
    layers = {{&d.channels, &diffuse_buffer()}, {&d.channels, &specular_buffer()}};
  else
    layers = {{&d.positions, &atlas_->level_layer(level)}};
  std::vector<float> steps;
  for (int i = 0; i < stroke.smooth().iterations; ++i) {
    steps.push_back(stroke.smooth().lambda);
    if (stroke.smooth().taubin && !stroke.smooth().target_colour)
      steps.push_back(stroke.smooth().mu);
  }
  for (const auto& [k, layer] : layers)
    d.smoothing->run(k->welded, *layer, l, set, weights, steps);
  phase_done(&StepPhases::transform);
  if (stroke.smooth().target_colour)
    q.finish();
  else
    geometry_done();
}

void PaintSurface::grab_step(const std::vector<DabSample>& samples, std::size_t index, bool mine)
{
  // The region under the first point is taken once; every later dab moves
  // it by the path's step, with the weights it had when taken.
  OpenStroke& o = *open_;
  GrabRegion& g = o.grab;
  BrushDab& dab = o.dab;
  if (index == 0) {
    g.held = false;
    if (!mine) // in a scene, the region is another object's
      return;
    dab.radius = o.stroke.brush.radius * samples.front().pressure;
    dab.strength = o.stroke.brush.strength * samples.front().pressure;
    if (!(dab.radius > 0.f))
      return;
    Vec3 normal;
    phase_start();
    g.patches = place(o.stroke, samples.front(), dab, normal);
    phase_done(&StepPhases::place);
    if (g.patches.empty()) {
      o.report.left_surface = true;
      o.ended = true;
      return;
    }
    g.held = true;
    g.at = samples.front().centre;
    return;
  }
  if (g.held)
    grab_move(samples[index].centre);
}

void PaintSurface::grab_move(const Vec3& to)
{
  OpenStroke& o = *open_;
  GrabRegion& g = o.grab;
  reshape(g.patches, o.dab, o.stroke, sub(to, g.at), g.moves == 0);
  ++g.moves;
  g.at = to;
  ++o.report.dabs_applied;
  o.report.patches_touched += g.patches.size();
}

void PaintSurface::grab_end(const Stroke& stroke)
{
  // The pull ends at the path's end, which the dabs' spacing may fall short of.
  const std::vector<DabSample> samples = stroke_samples(stroke);
  const bool last = stroke.points.size() > 1 && samples.back().centre != stroke.points.back();
  open_->report.dabs = samples.size() + (last ? 1 : 0);
  if (last && open_->grab.held)
    grab_move(stroke.points.back());
}

float PaintSurface::stroke_stretch()
{
  if (stretched_.empty())
    return 1.f;
  phase_start();
  const float worst = multires_->stretch(stretched_);
  phase_done(&StepPhases::rebuild);
  return worst;
}

void PaintSurface::refresh_geometry(const std::vector<int>& patches, const cl::Buffer* list)
{
  // The limit changed on the patches' sides and corners too, which every
  // patch sharing a corner with them stores: their tiles and bounds as well
  // (Atlas::neighbourhood(); with many patches made on the device).
  const PatchSet set = atlas_->neighbourhood(patches, list);
  phase_done(&StepPhases::lists);
  refresh_geometry(set);
}

void PaintSurface::refresh_geometry(const PatchSet& set)
{
  atlas_->update_limit(set); // and the patches' bounds
  phase_done(&StepPhases::limit);
}

} // namespace meshpaint
