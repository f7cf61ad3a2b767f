// What a painted surface is exported as: the one export path of the command
// line (`meshpaint paint -o`), vtkPaintSurface::ExportModel and the window.
#ifndef PaintingExport_h
#define PaintingExport_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "paint/paint_surface.h" // for meshpaint::PaintSurface

#include <string> // for std::string

namespace meshpaint {

//! The model level exports use unless told otherwise: two levels below the
//! painting level `level`, at least 1.
MESHPAINTVIS_EXPORT int default_model_level(int level);

//! What export_model() and export_painting() wrote.
struct PaintingExportReport
{
  std::string surface_path;  //!< DIR/surface.vtp; empty from export_model()
  std::size_t model_quads = 0;
  int map_width = 0, map_height = 0;
};

//! Creates DIR if missing and writes, each atomically, DIR/model.obj and
//! model.mtl at `model_level` (1 .. the painting level) and the PNG texture
//! maps diffuse, specular, roughness and displacement (the window's Ctrl+E).
//! \throw IOError when DIR cannot be created or a file not written.
MESHPAINTVIS_EXPORT PaintingExportReport export_model(PaintSurface& surface, int model_level, const std::string& dir);

//! export_model(), and before it DIR/surface.vtp: the painted limit surface
//! with its channel arrays (`meshpaint paint -o DIR`, ExportModel()).
//! \throw IOError when DIR cannot be created or a file not written.
MESHPAINTVIS_EXPORT PaintingExportReport export_painting(PaintSurface& surface, int model_level,
                                                         const std::string& dir);

//! Creates `dir` and its parents unless it exists.
//! \throw IOError when it cannot.
MESHPAINTVIS_EXPORT void make_directory(const std::string& dir);

} // namespace meshpaint

#endif
