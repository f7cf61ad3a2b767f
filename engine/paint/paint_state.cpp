// The painting surface's weld map, made on first use.

#include "paint/paint_state.h"

#include "atlas/weld.h"

namespace meshpaint {

const std::vector<int>& texel_vertices(const PaintState& state)
{
  if (state.weld_map.empty())
    state.weld_map = weld_map(state.atlas.topology(), state.layout());
  return state.weld_map;
}

} // namespace meshpaint
