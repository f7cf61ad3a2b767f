// Reading VTK's own polygon files (.vtp, legacy .vtk) and checking what any
// VTK reader delivers: sizes bounded before reading, messages kept instead
// of printed, non-finite points and cells naming missing points refused.
#ifndef PolyDataFiles_h
#define PolyDataFiles_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "mesh/base_mesh.h" // for meshpaint::BaseMesh, ImportOptions

#include <vtkAlgorithm.h>    // for vtkAlgorithm
#include <vtkPolyData.h>     // for vtkPolyData
#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <string> // for std::string

namespace meshpaint {

//! Whether `path` ends in .vtp or .vtk (any case).
MESHPAINTVIS_EXPORT bool is_polydata_path(const std::string& path);

//! Runs a reader whose file name is set: VTK's messages meanwhile are kept,
//! never printed (output window and logger restored after), and the first
//! becomes the error; the output must have points, all finite, and cells
//! naming only those points.
//! \throw InputError naming `path`, one line.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> read_checked(vtkAlgorithm* reader, const std::string& path);

//! A .vtp (VTK XML PolyData) or legacy .vtk polydata file, its header's
//! sizes checked against the file's length first, then read_checked().
//! \throw IOError when missing; InputError otherwise.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkPolyData> read_polydata_file(const std::string& path);

//! Polygons handed over in memory (Python, VTK pipelines) as a base mesh,
//! through the same import steps and checks as a file's (import_mesh()): its
//! points, its polygons, as the mesh's colours RGB bytes as other tools
//! write them (3 or 4 unsigned chars per point, alpha ignored: the point
//! scalars, or an array named Colors, RGB or RGBA), its point arrays for the
//! channels (take_channel_arrays(): by their name, as `diffuse`, or as
//! `options.arrays` says), an integer one named as label_array_names() as
//! labels, and the label classes of its field data label_ids, label_names
//! and label_colors. Messages start with `where`.
//! \throw InputError when there are no polygons, a point is not
//! finite, a polygon names a missing point, the mesh is unusable, an array
//! for a channel is missing or out of range, or the label classes are invalid.
MESHPAINTVIS_EXPORT BaseMesh import_polydata(vtkPolyData* poly, const std::string& name, const std::string& where,
                                             const ImportOptions& options = {});

//! A .vtp or .vtk file as a base mesh: its polygons through the import
//! steps of load_mesh() through import_polydata(), colours included.
//! \throw IOError, InputError as read_polydata_file() and import_mesh().
MESHPAINTVIS_EXPORT BaseMesh load_polydata_mesh(const std::string& path, const ImportOptions& options = {});

} // namespace meshpaint

#endif
