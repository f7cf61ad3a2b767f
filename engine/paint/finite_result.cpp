#include "paint/finite_result.h"

#include "core/format.h"    // for meshpaint::format_number
#include "mesh/base_mesh.h" // for meshpaint::kMaxCoordinate

#include <cmath>   // for std::isfinite, std::fabs
#include <numeric> // for std::iota

namespace meshpaint {

bool moves_surface(const Stroke& stroke)
{
  const ToolFamily family = tool_family(stroke);
  if (family == ToolFamily::Move || family == ToolFamily::Smooth)
    return true;
  const auto* paint = std::get_if<PaintSettings>(&stroke.settings);
  return paint && !paint->remover && paint->alpha[CHANNEL_DISPLACEMENT] > 0.f;
}

std::string surface_result_problem(PaintSurface& surface, std::uint64_t since)
{
  PatchChanges changes = surface.changes_since(since);
  if (changes.all) {
    changes.patches.resize(std::size_t(surface.atlas().layout(surface.level()).patches));
    std::iota(changes.patches.begin(), changes.patches.end(), 0);
  }
  const PaintedVertices v = surface.painted_vertices(changes.patches);
  const WeldedSurface& s = v.values.surface;
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    for (int a = 0; a < 3; ++a) {
      const float x = s.points[k][std::size_t(a)];
      if (!std::isfinite(x) || std::fabs(x) > kMaxCoordinate)
        return "it would move the surface to " + format_number(x) +
               " (results must be finite and at most 1e15 in magnitude); use a smaller amount or displacement";
      if (!s.normals.empty() && !std::isfinite(s.normals[k][std::size_t(a)]))
        return "it would leave the surface without finite normals; use a smaller amount or displacement";
    }
  }
  return "";
}

} // namespace meshpaint
