// Texture-space subsurface lighting (Ritschel et al., section 7) of a
// painting surface.
#pragma once

#include "core/vec.h"
#include "paint/paint_state.h"

#include <vector> // for std::vector

namespace meshpaint {

//! The irradiance max(0, n . light) of a directional light at every texel,
//! diffused over the atlas by `passes` smoothing passes, per welded vertex
//! in the order of PaintSurface::painted_surface().
//! \throw InputError when `towards_light` is zero; DeviceError when the
//! device fails.
std::vector<float> scattered_light(const PaintState& state, const Vec3& towards_light, int passes);

} // namespace meshpaint
