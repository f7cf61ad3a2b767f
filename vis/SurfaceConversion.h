// Moving surfaces between the engine and VTK.
#ifndef SurfaceConversion_h
#define SurfaceConversion_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "mesh/welded_surface.h" // for meshpaint::WeldedSurface
#include "paint/model_export.h" // for meshpaint::TextureMaps
#include "paint/paint_surface.h" // for meshpaint::PaintedSurface
#include "mesh/base_mesh.h"       // for meshpaint::BaseMesh
#include "project/labels.h"       // for meshpaint::LabelClass

#include <vtkImageData.h>    // for vtkImageData
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

//! Writes .vtp (XML, appended raw binary, zlib-compressed) atomically,
//! encoded in memory first.
//! \throw IOError when writing fails; StorageError when the disk is full.
MESHPAINTVIS_EXPORT void write_vtp(vtkPolyData* poly, const std::string& path);

//! Puts the label classes into the field data of `poly`: label_ids (int),
//! label_names (strings) and label_colors (unsigned char RGB, 3 components),
//! one tuple per class in the table's order; arrays of those names are
//! replaced. An empty table gives the three arrays with no tuples.
MESHPAINTVIS_EXPORT void add_label_classes(vtkPolyData* poly, const std::vector<LabelClass>& labels);

//! A colour component 0..1 as the byte 0..255 (clamped, rounded).
MESHPAINTVIS_EXPORT unsigned char colour_byte(float value);

//! `image` (8- or 16-bit, 1 to 4 components) encoded as PNG bytes.
//! \throw IOError naming `path` when VTK cannot encode it.
MESHPAINTVIS_EXPORT std::string png_bytes(vtkImageData* image, const std::string& path);

//! A texture map (`components` values 0..1 per pixel, rows top first) as
//! 8-bit PNG bytes, as write_texture_maps() writes it.
MESHPAINTVIS_EXPORT std::string map_png(const std::vector<float>& values, int width, int height, int components,
                                        const std::string& path);

} // namespace meshpaint

#endif
