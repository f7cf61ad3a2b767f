// The atlas's patch borders as lines over a painted surface: where one
// patch's texels end and the next patch's begin (the studio's patch wireframe).
#ifndef PatchBorders_h
#define PatchBorders_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkSmartPointer.h> // for vtkSmartPointer

class vtkPolyData;

namespace meshpaint {

//! `full` is a welded level surface with n x n quads per patch in patch
//! order, row by row (as weld() emits them, corners counter-clockwise from
//! the patch's (i, j) texel). Returns one closed polyline per patch along
//! its border, on `full`'s points (shared, not copied), so the lines lie on
//! the surface and follow its edits.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> patch_borders(vtkPolyData* full, int n);

} // namespace meshpaint

#endif
