// Smoothing passes and the smear brush's pick-up over a dab's patches.

#include "paint/smoothing.h"

#include "paint/colour_paint.h"
#include "paint/paint_device.h"

#include <utility> // for std::pair

namespace meshpaint {

void smooth_dab(const DabContext& context, const std::vector<int>& patches, const SmoothSettings& settings,
                int level, const cl::Buffer& weights)
{
  // Edges and corners are smoothed only where every patch sharing them is
  // in the brush; elsewhere their weight is zero anyway.
  const PaintState& s = context.state;
  PaintDevice& d = s.device;
  const LevelLayout l = s.atlas.layout(level);
  const bool everything = int(patches.size()) == l.patches;
  const PatchSet set = everything ? PatchSet() : s.atlas.patch_set(patches, Reach::All);
  std::vector<std::pair<LayerKernels*, const cl::Memory*>> layers;
  if (settings.target_colour)
    layers = {{&d.channels, &context.diffuse()}, {&d.channels, &context.specular()}};
  else
    layers = {{&d.positions, &s.atlas.level_layer(level)}};
  std::vector<float> steps;
  for (int i = 0; i < settings.iterations; ++i) {
    steps.push_back(settings.lambda);
    if (settings.taubin && !settings.target_colour)
      steps.push_back(settings.mu);
  }
  for (const auto& [k, layer] : layers)
    d.smoothing->run(k->welded, *layer, l, set, weights, steps);
}

void smear_dab(const DabContext& context, const std::vector<int>& patches, BrushDab dab,
               std::optional<std::array<Float4, 2>>& carried)
{
  const PaintState& s = context.state;
  PaintDevice& d = s.device;
  Runtime& rt = s.atlas.runtime();
  const LevelLayout l = s.layout();
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
    paint_dab(context, patches, dab);
  }
  const cl::Buffer list = device_ints(rt.context(), patches);
  const int count = int(patches.size());
  const std::size_t items = kGroup, texels = std::size_t(count) * l.tile * l.tile;
  const std::size_t groups = (texels + items - 1) / items;
  cl::Buffer partial(rt.context(), CL_MEM_WRITE_ONLY, 3 * groups * sizeof(Float4));
  d.dab = device_value(rt.context(), dab);
  launch(rt.queue(), d.dab_pickup, cl::NDRange(groups * items), cl::NDRange(items), s.atlas.limit_positions_layer(),
         s.atlas.limit_normals_layer(), grid(l), list, count, d.dab, d.unfold, d.stamp, context.diffuse(),
         context.specular(), partial, cl::Local(3 * items * sizeof(Float4)));
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

} // namespace meshpaint
