// VTK arrays over the engine's display arrays: the painted surface drawn
// from device memory that is host memory, without a copy.
#ifndef SharedArrays_h
#define SharedArrays_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "paint/display_arrays.h" // for meshpaint::DisplayArrays

#include <cstdint> // for std::uint64_t
#include <memory>  // for std::shared_ptr
#include <vector>  // for std::vector

class vtkPolyData;

namespace meshpaint {

//! Makes the point arrays of `poly` (to_polydata() of the same painted
//! surface) use the memory of `arrays` in place. Each VTK array keeps
//! `arrays` alive for as long as it lives, whoever holds it.
MESHPAINTVIS_EXPORT void share_arrays(vtkPolyData* poly, const std::shared_ptr<DisplayArrays>& arrays);

//! After a write into `arrays` (PaintSurface::display_arrays()):
//! marks modified the VTK arrays whose values changed since `seen` (the
//! DisplayArrays::version() of each when `poly` was last marked; updated
//! here), so only those are uploaded again, and wraps again any whose
//! memory moved. Returns whether memory moved (then any surface sharing the
//! old arrays must be rebuilt).
MESHPAINTVIS_EXPORT bool refresh_shared_arrays(vtkPolyData* poly, const std::shared_ptr<DisplayArrays>& arrays,
                                               std::vector<std::uint64_t>& seen);

} // namespace meshpaint

#endif
