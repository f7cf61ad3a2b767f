// Plain value types for host-side geometry.
#pragma once

#include <array> // for std::array

namespace meshpaint {

using Vec3 = std::array<float, 3>;
//! One atlas texel as the device stores it (xyz, w unused).
using Float4 = std::array<float, 4>;

} // namespace meshpaint
