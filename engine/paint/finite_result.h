// Whether a stroke left the painted surface finite and within range.
#pragma once

#include "paint/paint_surface.h"

#include <cstdint> // for std::uint64_t
#include <string>  // for std::string

namespace meshpaint {

//! Whether a stroke can move the painted surface: geometry tools, and paint
//! that reaches the displacement channel.
bool moves_surface(const Stroke& stroke);

//! Why the surface's patches changed after `since` (change_count()) are not
//! a usable result, or "" when they are: a displaced point or normal that is
//! not finite, or a point beyond kMaxCoordinate (where limit normals stop
//! being finite). Reads back only the changed tiles.
std::string surface_result_problem(PaintSurface& surface, std::uint64_t since);

} // namespace meshpaint
