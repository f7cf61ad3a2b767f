// Everything `meshpaint paint` writes for a painted surface, shared by the
// command line and vtkPaintSurface::ExportModel.
#ifndef PaintingExport_h
#define PaintingExport_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "paint/paint_surface.h" // for meshpaint::PaintSurface

#include <string> // for std::string

namespace meshpaint {

//! What export_painting() wrote.
struct PaintingExportReport
{
  std::string surface_path;  //!< DIR/surface.vtp
  std::size_t model_quads = 0;
  int map_width = 0, map_height = 0;
};

//! Creates DIR if missing and writes, each atomically: DIR/surface.vtp (the
//! painted limit surface with its channel arrays), DIR/model.obj and
//! model.mtl at `model_level` (1 .. the painting level), and the PNG texture
//! maps diffuse, specular, roughness and displacement.
//! \throw IOError when DIR cannot be created or a file not written.
MESHPAINTVIS_EXPORT PaintingExportReport export_painting(PaintSurface& surface, int model_level,
                                                         const std::string& dir);

} // namespace meshpaint

#endif
