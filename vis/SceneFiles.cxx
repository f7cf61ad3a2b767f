#include "SceneFiles.h"

#include "PaintingExport.h"    // for meshpaint::export_model, make_directory
#include "SurfaceConversion.h" // for meshpaint::write_vtp, add_label_classes

#include "core/atomic_file.h"        // for meshpaint::write_bytes_atomically, AtomicWriteBatch
#include "paint/paint_scene.h"       // for meshpaint::PaintScene
#include "project/project_surface.h" // for meshpaint::save_painted_project

namespace meshpaint {

std::string save_session(PaintScene& scene, const std::string& recording,
                         const std::function<vtkPolyData*(std::size_t)>& drawn,
                         const std::vector<LabelClass>& labels, const Project* project, ProjectOrigin& origin,
                         const std::string& dir)
{
  // One recording for the scene; each object's surface in its own folder.
  make_directory(dir);
  write_bytes_atomically(dir + "/strokes.json", {recording});
  for (std::size_t o = 0; o < scene.size(); ++o) {
    const std::string folder = scene.folder(dir, o);
    make_directory(folder);
    // As `meshpaint paint -o` writes it: with the label classes as field data.
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->ShallowCopy(drawn(o));
    add_label_classes(surface, labels);
    write_vtp(surface, folder + "/surface.vtp");
  }
  if (project) {
    Project base = *project;
    base.origin = origin;
    origin = save_painted_project(scene.surface(0), std::move(base), scene.folder(dir, 0) + "/surface.meshpaint");
  }
  const std::string surfaces =
    scene.size() == 1 ? "surface.vtp" : std::to_string(scene.size()) + " objects' surface.vtp";
  return "saved " + dir + "/strokes.json, " + surfaces + (project ? " and surface.meshpaint" : "");
}

std::string export_scene(PaintScene& scene, int model_level, const std::string& dir, CancelFlag cancel)
{
  AtomicWriteBatch batch; // every object's files, or none
  for (std::size_t o = 0; o < scene.size(); ++o)
    export_model(scene.surface(o), model_level, scene.folder(dir, o), cancel);
  stop_if_cancelled(cancel);
  batch.commit();
  return "exported " + scene.folder(dir, 0) + "/model.obj" + (scene.size() > 1 ? " and the other objects'" : "");
}

} // namespace meshpaint
