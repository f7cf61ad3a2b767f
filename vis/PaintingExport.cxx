#include "PaintingExport.h"

#include "SurfaceConversion.h" // for to_polydata, write_vtp, write_texture_maps

#include "core/atomic_file.h"   // for meshpaint::write_bytes_atomically, AtomicWriteBatch
#include "core/errors.h"        // for meshpaint::IOError, InputError
#include "core/format.h"        // for meshpaint::lower_extension
#include "paint/gltf_export.h"  // for meshpaint::gltf_bytes, metallic_roughness_map
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
  namespace fs = std::filesystem;
  std::vector<std::string> missing; // deepest first
  std::error_code ec;
  for (fs::path p = fs::absolute(dir, ec); !ec && !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p.string());
    if (p == p.parent_path())
      break;
  }
  fs::create_directories(dir, ec);
  if (ec)
    throw IOError("cannot create '" + dir + "': " + ec.message());
  if (AtomicWriteBatch* batch = AtomicWriteBatch::current())
    for (const std::string& made : missing)
      batch->made_directory(made);
}

namespace {

//! The points between an export's steps: where a cancel is looked at and
//! progress counted.
struct ExportSteps
{
  CancelFlag cancel;
  ProgressTask* task = nullptr;
  std::size_t done = 0;
  void next()
  {
    stop_if_cancelled(cancel);
    if (task)
      task->step(++done);
  }
};

//! ExportSteps::next() calls in write_model().
constexpr std::size_t kModelSteps = 4;

PaintingExportReport write_model(PaintSurface& surface, int model_level, const std::string& dir, ExportSteps& steps)
{
  ExportModel model;
  TextureMaps maps;
  build_export(surface, model_level, model, maps);
  steps.next();
  write_texture_maps(maps, dir);
  steps.next();
  write_obj_model(model, maps, dir);
  GltfImages images;
  for (const bool inside : {false, true}) {
    if (inside && maps.inside_diffuse.empty())
      break;
    const std::string prefix = inside ? "inside_" : "";
    GltfMaterialImages& side = inside ? images.inside : images.outside;
    side.base_colour.uri = prefix + "diffuse.png";
    side.specular.uri = prefix + "specular.png";
    side.metallic_roughness.uri = prefix + "metallic_roughness.png";
    const std::string path = dir + "/" + side.metallic_roughness.uri;
    const std::string png = map_png(metallic_roughness_map(inside ? maps.inside_roughness : maps.roughness),
                                    maps.width, maps.height, 3, path);
    write_bytes_atomically(path, {png});
  }
  steps.next();
  const std::string gltf = gltf_bytes(model, maps, images, false);
  write_bytes_atomically(dir + "/model.gltf", {gltf});
  steps.next();
  PaintingExportReport report;
  report.model_quads = model.mesh.quads.size();
  report.map_width = maps.width;
  report.map_height = maps.height;
  return report;
}

} // namespace

PaintingExportReport export_model(PaintSurface& surface, int model_level, const std::string& dir, CancelFlag cancel)
{
  stop_if_cancelled(cancel);
  AtomicWriteBatch batch; // every file of the model, or none
  make_directory(dir);
  ExportSteps steps{cancel};
  PaintingExportReport report = write_model(surface, model_level, dir, steps);
  batch.commit();
  return report;
}

PaintingExportReport export_painting(PaintSurface& surface, int model_level, const std::string& dir,
                                     const std::vector<LabelClass>& labels, Progress* progress)
{
  AtomicWriteBatch batch; // the surface and the model together
  make_directory(dir);
  ProgressTask task(progress, "writing " + dir, 1 + kModelSteps);
  ExportSteps steps{nullptr, &task};
  const std::string surface_path = dir + "/surface.vtp";
  vtkSmartPointer<vtkPolyData> poly = to_polydata(surface.painted_surface());
  add_label_classes(poly, labels);
  write_vtp(poly, surface_path);
  steps.next();
  PaintingExportReport report = write_model(surface, model_level, dir, steps);
  batch.commit();
  report.surface_path = surface_path;
  return report;
}

void export_gltf(PaintSurface& surface, int model_level, const std::string& path, CancelFlag cancel)
{
  const std::string ext = lower_extension(path);
  if (ext != ".glb" && ext != ".gltf")
    throw InputError("--gltf must name a .glb or .gltf file, not '" + path + "'");
  stop_if_cancelled(cancel);
  ExportModel model;
  TextureMaps maps;
  build_export(surface, model_level, model, maps);
  stop_if_cancelled(cancel);
  GltfImages images;
  images.outside.base_colour.png = map_png(maps.diffuse, maps.width, maps.height, 3, path);
  images.outside.specular.png = map_png(maps.specular, maps.width, maps.height, 3, path);
  images.outside.metallic_roughness.png =
    map_png(metallic_roughness_map(maps.roughness), maps.width, maps.height, 3, path);
  if (!maps.inside_diffuse.empty()) {
    images.inside.base_colour.png = map_png(maps.inside_diffuse, maps.width, maps.height, 3, path);
    images.inside.specular.png = map_png(maps.inside_specular, maps.width, maps.height, 3, path);
    images.inside.metallic_roughness.png =
      map_png(metallic_roughness_map(maps.inside_roughness), maps.width, maps.height, 3, path);
  }
  stop_if_cancelled(cancel);
  const std::string bytes = gltf_bytes(model, maps, images, ext == ".glb");
  stop_if_cancelled(cancel); // the last boundary: the write below renames its file into place
  write_bytes_atomically(path, {bytes});
}

} // namespace meshpaint
