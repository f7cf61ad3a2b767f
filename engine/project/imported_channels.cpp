#include "project/imported_channels.h"

#include "project/refined_values.h"
#include "project/vertex_channels.h"

#include <algorithm> // for std::min, std::max
#include <array>     // for std::array

namespace meshpaint {
namespace {

//! Up to three components of a channel at a vertex, as OpenSubdiv's primvar
//! interpolation wants them.
struct Components
{
  std::array<float, 3> c{0.f, 0.f, 0.f};
  void Clear(void* = nullptr) { c = {0.f, 0.f, 0.f}; }
  void AddWithWeight(const Components& src, float w)
  {
    c[0] += w * src.c[0];
    c[1] += w * src.c[1];
    c[2] += w * src.c[2];
  }
};

//! Refines `k` values per base vertex (`flat`) and sets them as `channel`.
void set_refined(PaintSurface& surface, const std::string& channel, int k, const float* flat)
{
  const std::size_t vertices = surface.atlas().base_mesh().vertex_count();
  std::vector<Components> coarse(vertices);
  for (std::size_t v = 0; v < vertices; ++v)
    for (int a = 0; a < k; ++a)
      coarse[v].c[std::size_t(a)] = flat[v * std::size_t(k) + std::size_t(a)];
  const std::vector<Components> fine = refined_to_painting_level(surface, std::move(coarse));
  // Catmull-Clark's weights are positive: only rounding can leave the range.
  const bool unit = channel != "displacement";
  std::vector<float> values(fine.size() * std::size_t(k));
  for (std::size_t v = 0; v < fine.size(); ++v)
    for (int a = 0; a < k; ++a) {
      const float x = fine[v].c[std::size_t(a)];
      values[v * std::size_t(k) + std::size_t(a)] = unit ? std::min(1.0f, std::max(0.0f, x)) : x;
    }
  set_vertex_channel(surface, channel, values);
}

} // namespace

void apply_imported_channels(PaintSurface& surface)
{
  // The atlas's base mesh, reordered along with its colours and channels.
  const BaseMesh& base = surface.atlas().base_mesh();
  if (!base.colours.empty() && base.colours.size() == base.vertex_count())
    set_refined(surface, "diffuse", 3, base.colours[0].data());
  for (const ChannelArray& a : base.channels)
    if (a.values.size() == base.vertex_count() * std::size_t(a.components))
      set_refined(surface, a.channel, a.components, a.values.data());
}

} // namespace meshpaint
