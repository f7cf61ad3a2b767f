// Level-of-detail drawing: a coarser tessellation of a painted surface that
// shares its points and arrays, and the frame timing that picks its level.
#ifndef LevelOfDetail_h
#define LevelOfDetail_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <array> // for std::array

class vtkPolyData;

namespace meshpaint {

//! `full` is a welded level surface with n x n quads per patch in patch
//! order, row by row (as weld() emits them). Returns a surface with the same
//! points and point arrays (shared, not copied) and n/stride x n/stride quads
//! per patch, whose corners are every stride-th texel: the texels level
//! l - log2(stride) has, at their finest-level positions, normals and
//! channels. `stride` is a power of two dividing n.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> coarser_quads(vtkPolyData* full, int n, int stride);

//! The time frames at rest take per quad, and the level of detail chosen
//! from it.
class MESHPAINTVIS_EXPORT FrameTiming
{
public:
  //! Forgets the frames timed (other objects draw at another rate).
  void reset() { ms_per_quad_ = 0; }
  //! A frame at rest: `quads` drawn in `ms` in a window of width x height.
  //! The least time per quad seen is the drawing itself, without uploads
  //! after edits or a busy host; a new window size starts afresh (a
  //! software rasterizer's cost is much per pixel).
  void add_frame(double ms, int width, int height, double quads);
  //! The finest level below `level` (at least 1) whose drawing, at the rate
  //! timed, takes at most half a frame at `frame_rate` frames per second (the
  //! other half is left to the brush step and the display update); `quads`:
  //! the quads at `level`.
  int automatic_level(int level, double frame_rate, double quads) const;

private:
  double ms_per_quad_ = 0; // 0: none timed yet
  std::array<int, 2> timed_size_{};
};

} // namespace meshpaint

#endif
