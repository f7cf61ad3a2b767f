// The channel buffers of the side a dab paints.

#include "paint/dab_context.h"

#include "paint/paint_device.h"

namespace meshpaint {

cl::Buffer& DabContext::diffuse() const { return inside ? state.device.inside_diffuse : state.device.diffuse; }
cl::Buffer& DabContext::specular() const { return inside ? state.device.inside_specular : state.device.specular; }
cl::Buffer& DabContext::material() const { return inside ? state.device.inside_material : state.device.material; }

} // namespace meshpaint
