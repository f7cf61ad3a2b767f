// Level-of-detail drawing: a coarser tessellation of a painted surface that
// shares its points and arrays.
#ifndef LevelOfDetail_h
#define LevelOfDetail_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkSmartPointer.h> // for vtkSmartPointer

class vtkPolyData;

namespace meshpaint {

//! `full` is a welded level surface with n x n quads per patch in patch
//! order, row by row (as weld() emits them). Returns a surface with the same
//! points and point arrays (shared, not copied) and n/stride x n/stride quads
//! per patch, whose corners are every stride-th texel: the texels level
//! l - log2(stride) has, at their finest-level positions, normals and
//! channels. `stride` is a power of two dividing n.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> coarser_quads(vtkPolyData* full, int n, int stride);

} // namespace meshpaint

#endif
