// Snapshots of layer tiles: gathered from the device into one list per
// layer, and scattered back.

#include "paint/snapshots.h"

#include "paint/paint_device.h"

namespace meshpaint {

std::pair<LayerKernels*, const cl::Memory*> snapshot_layer(const PaintState& state, int id, int edit_level)
{
  PaintDevice& d = state.device;
  Atlas& atlas = state.atlas;
  switch (id) {
  case kEditPositions: return {&d.positions, &atlas.level_layer(edit_level)};
  case kPositions: return {&d.positions, &atlas.level_layer(state.level)};
  case kDiffuse: return {&d.channels, &d.diffuse};
  case kSpecular: return {&d.channels, &d.specular};
  case kInsideDiffuse: return {&d.channels, &d.inside_diffuse};
  case kInsideSpecular: return {&d.channels, &d.inside_specular};
  case kInsideMaterial: return {&d.channels, &d.inside_material};
  case kLimitPositions: return {&d.positions, &atlas.limit_positions_layer()};
  case kLimitNormals: return {&d.positions, &atlas.limit_normals_layer()};
  default: return {&d.channels, &d.material};
  }
}

Snapshot take_snapshot(const PaintState& state, const std::vector<int>& patches, const std::vector<int>& layers,
                       int edit_level)
{
  Snapshot s;
  s.patches = patches;
  s.layer_ids = layers;
  s.edit_level = edit_level;
  if (state.multires)
    s.multires = state.multires->state();
  if (patches.empty())
    return s;
  Runtime& rt = state.atlas.runtime();
  const cl::Buffer list = device_ints(rt.context(), patches);
  const std::size_t most = patches.size() * std::size_t(state.layout().tile) * state.layout().tile;
  cl::Buffer out(rt.context(), CL_MEM_WRITE_ONLY, sizeof(Float4) * most);
  for (const int id : layers) {
    const LevelLayout l = state.atlas.layout(id == kEditPositions ? edit_level : state.level);
    const std::size_t n = patches.size() * std::size_t(l.tile) * l.tile;
    const auto tiles = range_tiles(l, int(patches.size()));
    const auto [kernels, memory] = snapshot_layer(state, id, edit_level);
    launch(rt.queue(), kernels->gather_tiles, tiles.first, tiles.second, *memory, grid(l), list, int(patches.size()),
           out);
    s.layers.emplace_back(n);
    rt.queue().enqueueReadBuffer(out, CL_TRUE, 0, sizeof(Float4) * n, s.layers.back().data());
  }
  return s;
}

void put_back_layer(const PaintState& state, const Snapshot& s, std::size_t k, const cl::Buffer& list)
{
  Runtime& rt = state.atlas.runtime();
  const int id = s.layer_ids[k];
  const LevelLayout l = state.atlas.layout(id == kEditPositions ? s.edit_level : state.level);
  const auto tiles = range_tiles(l, int(s.patches.size()));
  const auto [kernels, memory] = snapshot_layer(state, id, s.edit_level);
  // Copied at creation: no wait needed for the host data.
  const cl::Buffer in = device_copy(rt.context(), s.layers[k]);
  launch(rt.queue(), kernels->scatter_tiles, tiles.first, tiles.second, *memory, grid(l), list,
         int(s.patches.size()), in);
}

} // namespace meshpaint
