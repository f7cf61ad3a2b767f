// The engine's SurfaceQuery answered by VTK's static cell locator.
#ifndef VtkSurfaceQuery_h
#define VtkSurfaceQuery_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "project/scan_fit.h" // for meshpaint::SurfaceQueryFactory

namespace meshpaint {

//! Builds queries over triangles with vtkStaticCellLocator: closest points
//! by FindClosestPoint, segment hits by IntersectWithLine (the hit nearest
//! the segment's start).
MESHPAINTVIS_EXPORT SurfaceQueryFactory vtk_surface_queries();

} // namespace meshpaint

#endif
