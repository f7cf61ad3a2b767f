// Moving surfaces between the engine and VTK.
#ifndef SurfaceConversion_h
#define SurfaceConversion_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "mesh/welded_surface.h" // for meshpaint::WeldedSurface
#include "paint/model_export.h" // for meshpaint::TextureMaps
#include "paint/paint_surface.h" // for meshpaint::PaintedSurface
#include "mesh/base_mesh.h"       // for meshpaint::BaseMesh

#include <vtkPolyData.h>     // for vtkPolyData
#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <string> // for std::string

namespace meshpaint {

//! Quads as cells, normals (when present) as the point array "Normals".
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> to_polydata(const WeldedSurface& surface);

//! The painted surface with point arrays diffuse, specular (3 components),
//! roughness, displacement, mask (floats), label (int) and Normals.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> to_polydata(const PaintedSurface& surface);

//! Writes `surface` into `poly`, made by to_polydata() from a surface of the
//! same topology, changing only the arrays whose contents differ (points,
//! Normals, channels) and marking only those modified, so that a renderer
//! uploads only what changed. Returns how many arrays changed.
//! \throw std::invalid_argument when the sizes do not match.
MESHPAINTVIS_EXPORT int update_polydata(vtkPolyData* poly, const PaintedSurface& surface);

//! The same for some vertices only (PaintSurface::painted_vertices): writes
//! their values into the arrays of `poly`, marking modified only the arrays
//! where a value changed. Returns how many arrays changed.
//! \throw std::invalid_argument when ids or arrays do not match.
MESHPAINTVIS_EXPORT int update_polydata(vtkPolyData* poly, const PaintedVertices& update);

//! The polygons of `poly` (other cells ignored) as a checked base mesh.
//! \throw InputError as make_base_mesh does.
MESHPAINTVIS_EXPORT BaseMesh to_base_mesh(vtkPolyData* poly, const std::string& name);

//! Writes the texture maps as PNG files DIR/diffuse.png, specular.png (8-bit
//! RGB), roughness.png (8-bit grey) and displacement.png (16-bit grey over
//! the map's displacement range), each atomically.
MESHPAINTVIS_EXPORT void write_texture_maps(const TextureMaps& maps, const std::string& dir);

//! Writes .vtp (XML, appended raw binary, zlib-compressed) atomically.
//! \throw IOError when writing fails.
MESHPAINTVIS_EXPORT void write_vtp(vtkPolyData* poly, const std::string& path);

} // namespace meshpaint

#endif
