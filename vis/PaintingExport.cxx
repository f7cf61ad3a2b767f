#include "PaintingExport.h"

#include "SurfaceConversion.h" // for to_polydata, write_vtp, write_texture_maps

#include "core/errors.h"         // for meshpaint::IOError
#include "paint/model_export.h" // for meshpaint::build_export, meshpaint::write_obj_model

#include <algorithm>  // for std::max
#include <filesystem> // for std::filesystem::create_directories

namespace meshpaint {

int default_model_level(int level)
{
  return std::max(1, level - 2);
}

void make_directory(const std::string& dir)
{
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw IOError("cannot create '" + dir + "': " + ec.message());
}

PaintingExportReport export_model(PaintSurface& surface, int model_level, const std::string& dir)
{
  make_directory(dir);
  ExportModel model;
  TextureMaps maps;
  build_export(surface, model_level, model, maps);
  write_texture_maps(maps, dir);
  write_obj_model(model, maps, dir);
  PaintingExportReport report;
  report.model_quads = model.mesh.quads.size();
  report.map_width = maps.width;
  report.map_height = maps.height;
  return report;
}

PaintingExportReport export_painting(PaintSurface& surface, int model_level, const std::string& dir)
{
  make_directory(dir);
  const std::string surface_path = dir + "/surface.vtp";
  write_vtp(to_polydata(surface.painted_surface()), surface_path);
  PaintingExportReport report = export_model(surface, model_level, dir);
  report.surface_path = surface_path;
  return report;
}

} // namespace meshpaint
