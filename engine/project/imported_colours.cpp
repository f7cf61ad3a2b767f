#include "project/imported_colours.h"

#include "mesh/far_refiner.h"
#include "project/vertex_channels.h"
#include "reference/opensubdiv_reference.h"

#include <algorithm> // for std::min, std::max

namespace meshpaint {

void apply_imported_colours(PaintSurface& surface)
{
  // The atlas's base mesh, reordered along with its colours.
  const BaseMesh& base = surface.atlas().base_mesh();
  if (base.colours.size() != base.vertex_count())
    return;
  const int level = surface.level();
  auto refiner = make_refiner(base);
  refine_uniform(*refiner, level, false);
  const std::vector<Vec3> fine = interpolate_levels(*refiner, base.colours)[std::size_t(level)];
  // Each welded vertex of the painting level, as OpenSubdiv numbers it.
  const std::vector<int> order = opensubdiv_vertex_order(base, surface.atlas().topology(), level);
  std::vector<float> values(order.size() * 3);
  for (std::size_t v = 0; v < order.size(); ++v)
    for (int a = 0; a < 3; ++a)
      values[v * 3 + std::size_t(a)] = std::min(1.0f, std::max(0.0f, fine[std::size_t(order[v])][a]));
  set_vertex_channel(surface, "diffuse", values);
}

} // namespace meshpaint
