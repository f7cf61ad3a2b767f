// Handing a project's channels (and edits) back to the scan it was made
// for, on the scan's own vertices.
#ifndef ScanTransfer_h
#define ScanTransfer_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "mesh/welded_surface.h" // for meshpaint::WeldedSurface
#include "paint/paint_surface.h" // for meshpaint::PaintedSurface

#include <vtkPolyData.h>     // for vtkPolyData
#include <vtkSmartPointer.h> // for vtkSmartPointer

#include "project/labels.h" // for meshpaint::LabelClass

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! File extensions read_scan() reads, lower case with the dot.
MESHPAINTVIS_EXPORT const std::vector<std::string>& scan_extensions();

//! A scan exactly as its file holds it: .ply, .obj and .stl checked by
//! read_mesh_file() first, then read through VTK's readers (every point,
//! cell and array); .off as read_mesh_file() reads it, points and polygons
//! in file order; .vtp through VTK's XML reader after its size attributes
//! are checked against the file. VTK's messages become the error, never
//! printed; non-finite points and cells naming missing points are refused.
//! \throw IOError when the file cannot be read; InputError, one line, for
//! another format or a malformed, truncated or inconsistent file.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> read_scan(const std::string& path);

//! What transfer_to_scan() found.
struct TransferReport
{
  double max_distance = 0;  //!< largest distance from a scan vertex to the reference surface
  double rms_distance = 0;
  double max_moved = 0;     //!< with geometry: largest distance a vertex moved
};

//! Adds to `scan` the point arrays label (int), diffuse, specular (3
//! floats), roughness and displacement, each scan vertex taking the values
//! of the painted surface where the vertex's closest point on `reference`
//! lies (labels from the nearest surface vertex, never blended; the rest
//! interpolated). With `geometry`, each vertex also moves by the painted
//! surface's displacement from the reference there (sculpting, smoothing,
//! the displacement channel). Arrays of those names are replaced; every
//! other point, cell and array stays.
//! \pre `painted.surface` and `reference` are welded alike (same quads).
MESHPAINTVIS_EXPORT TransferReport transfer_to_scan(const PaintedSurface& painted, const WeldedSurface& reference,
                                                    vtkPolyData* scan, bool geometry);

//! Writes a scan as binary PLY through OpenMesh: points in order, polygons,
//! the diffuse colour as uchar vertex properties red, green and blue (what
//! MeshLab and CloudCompare show), and every point and cell array as vertex
//! and face properties, one per component (NAME for one component;
//! NAME_r/_g/_b for diffuse and specular, NAME_x/_y/_z for other 3-component
//! arrays, NAME_0.. otherwise); integer arrays (the label) as int32, others
//! float32. Encoded in memory, then written atomically.
//! \throw InputError when the scan has vertex, line or strip cells or a
//! polygon OpenMesh cannot keep (PLY through OpenMesh holds polygons only);
//! IOError when writing fails.
MESHPAINTVIS_EXPORT void write_scan_ply(vtkPolyData* scan, const std::string& path);

//! Writes a transferred scan by the extension of `path`: .ply through
//! write_scan_ply(), .vtp with the label classes as field data
//! (add_label_classes()); atomically (`meshpaint transfer -o`, the studio's
//! export of the labelled scan).
//! \throw InputError for another extension; as write_scan_ply() and write_vtp().
MESHPAINTVIS_EXPORT void write_transferred_scan(vtkPolyData* scan, const std::string& path,
                                                const std::vector<LabelClass>& labels);

} // namespace meshpaint

#endif
