// Host memory a fit of a scan needs, worked out from the scan's size before
// anything is read, so that `meshpaint info` can say whether a fit fits.
#pragma once

#include <cstddef> // for std::size_t

namespace meshpaint {

//! What a fit of a scan needs at its peak.
struct FitMemory
{
  std::size_t base_faces = 0; //!< triangles of the decimated base mesh
  std::size_t points = 0;     //!< finest-level points fitted (about)
  std::size_t bytes = 0;      //!< peak host memory, device memory of a CPU device included
};

//! The peak host memory of `meshpaint fit` on a scan of `scan_triangles`
//! triangles, decimated to a budget of `base_faces` (none when the scan has
//! fewer triangles), at
//! atlas `level`. Linear in the scan's triangles (its mesh, the decimation's
//! half-edge mesh, the AABB tree of the queries) and in the points fitted
//! (the atlas, on a CPU device in host memory, and the fit's arrays per
//! point); the constants are the bytes measured per triangle and per point
//! by `meshpaint bench fit` (docs/benchmarks.md), with a margin of 20%.
FitMemory plan_fit_memory(std::size_t scan_triangles, std::size_t base_faces, int level);

} // namespace meshpaint
