// Undo snapshots: the tiles a stroke is about to change, taken from the
// device before its first dab there, and put back (with the state of the
// multiresolution details) by undo and redo.

#include "paint/paint_device.h"

#include <algorithm> // for std::find, std::max

namespace meshpaint {

std::pair<LayerKernels*, const cl::Memory*> PaintSurface::layer(int id, int edit_level)
{
  PaintDevice& d = *device_;
  switch (id) {
  case kEditPositions: return {&d.positions, &atlas_->level_layer(edit_level)};
  case kPositions: return {&d.positions, &atlas_->level_layer(level_)};
  case kDiffuse: return {&d.channels, &d.diffuse};
  case kSpecular: return {&d.channels, &d.specular};
  case kInsideDiffuse: return {&d.channels, &d.inside_diffuse};
  case kInsideSpecular: return {&d.channels, &d.inside_specular};
  case kInsideMaterial: return {&d.channels, &d.inside_material};
  case kLimitPositions: return {&d.positions, &atlas_->limit_positions_layer()};
  case kLimitNormals: return {&d.positions, &atlas_->limit_normals_layer()};
  default: return {&d.channels, &d.material};
  }
}

Snapshot PaintSurface::take_snapshot(const std::vector<int>& patches, const std::vector<int>& layers, int edit_level)
{
  Snapshot s;
  s.patches = patches;
  s.layer_ids = layers;
  s.edit_level = edit_level;
  if (multires_)
    s.multires = multires_->state();
  if (patches.empty())
    return s;
  Runtime& rt = atlas_->runtime();
  const cl::Buffer list = device_ints(rt.context(), patches);
  const std::size_t most = patches.size() * std::size_t(atlas_->layout(level_).tile) * atlas_->layout(level_).tile;
  cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(Float4) * most);
  for (const int id : layers) {
    const LevelLayout l = atlas_->layout(id == kEditPositions ? edit_level : level_);
    const std::size_t n = patches.size() * std::size_t(l.tile) * l.tile;
    const auto tiles = range_tiles(l, int(patches.size()));
    const auto [kernels, memory] = layer(id, edit_level);
    launch(rt.queue(), kernels->gather_tiles, tiles.first, tiles.second, *memory, grid(l), list, int(patches.size()),
           out);
    s.layers.emplace_back(n);
    rt.queue().enqueueReadBuffer(out, CL_TRUE, 0, sizeof(Float4) * n, s.layers.back().data());
  }
  return s;
}

void PaintSurface::restore(const Snapshot& s)
{
  for (const int id : s.layer_ids) // the tiles put back may carry a mask
    mask_painted_ = mask_painted_ || id == kMaterial || id == kInsideMaterial;
  Runtime& rt = atlas_->runtime();
  const cl::Buffer list = s.patches.empty() ? cl::Buffer() : device_ints(rt.context(), s.patches);
  const auto scatter = [&](std::size_t k) {
    const int id = s.layer_ids[k];
    const LevelLayout l = atlas_->layout(id == kEditPositions ? s.edit_level : level_);
    const auto tiles = range_tiles(l, int(s.patches.size()));
    const auto [kernels, memory] = layer(id, s.edit_level);
    // Copied at creation (COPY_HOST_PTR): no wait needed for the host data.
    const cl::Buffer in(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(Float4) * s.layers[k].size(),
                        const_cast<Float4*>(s.layers[k].data()));
    launch(rt.queue(), kernels->scatter_tiles, tiles.first, tiles.second, *memory, grid(l), list,
           int(s.patches.size()), in);
  };
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
    refresh_geometry(s.patches);
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
  Snapshot s = take_snapshot(fresh, stroke_layers_, stroke_before_.edit_level); // flags only once the tiles are safe
  for (const int p : fresh)
    in_stroke_[std::size_t(p)] = 1;
  stroke_before_.layer_ids = s.layer_ids;
  stroke_before_.patches.insert(stroke_before_.patches.end(), s.patches.begin(), s.patches.end());
  stroke_before_.layers.resize(std::max(stroke_before_.layers.size(), s.layers.size()));
  for (std::size_t k = 0; k < s.layers.size(); ++k)
    stroke_before_.layers[k].insert(stroke_before_.layers[k].end(), s.layers[k].begin(), s.layers[k].end());
}

bool PaintSurface::undo()
{
  if (!step(true))
    return false;
  undone_.push_back(std::move(history_.back()));
  history_.pop_back();
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
  Snapshot now = take_snapshot(target.patches, target.layer_ids, target.edit_level);
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
