// Texture-space subsurface lighting (Ritschel et al., section 7).

#include "paint/subsurface_light.h"

#include "paint/paint_device.h"

#include "core/errors.h"

#include <cmath> // for std::sqrt

namespace meshpaint {

std::vector<float> scattered_light(const PaintState& state, const Vec3& light, int passes)
{
  PaintDevice& d = state.device;
  Runtime& rt = state.atlas.runtime();
  cl::CommandQueue& q = rt.queue();
  const LevelLayout l = state.layout();
  const float len = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  if (!(len > 0.f))
    throw InputError("the light's direction must not be zero");
  try {
    cl::Kernel irradiance(d.positions.program, "irradiance");
    const auto tiles = range_tiles(l, l.patches);
    launch(q, irradiance, tiles.first, tiles.second, state.atlas.limit_normals_layer(), grid(l), l.patches,
           cl_float4{{light[0] / len, light[1] / len, light[2] / len, 0.f}}, d.channel_work);
    // Diffusion over the whole surface: the smoothing passes at full weight.
    q.enqueueFillBuffer(d.weights, 1.f, 0, l.texels() * sizeof(float));
    const std::vector<Float4> welded = d.smoothing->run_welded(d.channels.welded, d.channel_work, l, d.weights,
                                                               std::vector<float>(std::size_t(passes), 0.5f));
    std::vector<float> out(welded.size());
    for (std::size_t v = 0; v < welded.size(); ++v)
      out[v] = welded[v][0];
    return out;
  } catch (const cl::Error& e) {
    throw DeviceError("the subsurface light failed on " + rt.info().name + ": " + describe(e));
  }
}

} // namespace meshpaint
