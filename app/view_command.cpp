// meshpaint view: the studio, the painting window, on one mesh or project or
// on a scene of several meshes.

#include "commands.h"
#include "picture_options.h"

#include "DisplayCheck.h"
#include "RasterIO.h"
#include "Studio.h"
#include "vtkPaintView.h"

#include "atlas/patch_layout.h" // for meshpaint::kMaxLevel
#include "core/errors.h"
#include "core/format.h"
#include "project/labels.h" // for meshpaint::load_labels

#include <vtkNew.h> // for vtkNew

#include <algorithm> // for std::any_of
#include <iostream>  // for std::cout, std::cerr

namespace meshpaint::cli {
namespace {

constexpr int kDefaultViewLevelMax = 3;

//! The finest level up to 3 whose surfaces have at most about 1.5M quads in
//! all, so that a software renderer still draws them interactively.
int default_view_level(const std::vector<MeshOrProject>& inputs)
{
  double quads = 0;
  for (const MeshOrProject& input : inputs)
    for (int size : input.mesh().face_sizes)
      quads += size; // level 1: one quad per face corner
  int level = 1;
  while (level < kDefaultViewLevelMax && quads * 4 <= 1.5e6) {
    quads *= 4;
    ++level;
  }
  return level;
}

} // namespace

int view_command(const Argv& argv)
{
  Args args("view", argv, {"--no-weld"}, {"--strokes", "--level", "--lod", "-o", "--size", "--device", "--storage",
                                              "--import-array", "--labels"});
  args.expect_positionals(1, 64, "MESH...|PROJECT [--strokes S.json] [--labels labels.json] [--level L] [--lod L] [-o DIR] [--size WxH]");
  const std::vector<std::string>& paths = args.positionals();
  if (paths.size() > 1)
    for (const std::string& path : paths)
      if (is_project_path(path))
        throw InputError("'" + path + "' is a project: view opens one PROJECT alone, or several meshes");
  // Everything is checked before the window opens.
  StrokeScript script;
  if (args.has("--strokes")) {
    script = load_stroke_script(args.value("--strokes"));
    load_stroke_rasters(script);
  }
  const PictureOptions picture = picture_options(args);
  if (args.has("--storage"))
    parse_storage(args.value("--storage"));
  const std::vector<LabelClass> new_labels =
    args.has("--labels") ? load_labels(args.value("--labels")) : std::vector<LabelClass>();
  // The flags' ranges as far as they are known before the meshes are read:
  // without --level, meshes are viewed at level 3 at most, projects at theirs.
  const bool projects = std::any_of(paths.begin(), paths.end(), is_project_path);
  const int asked_level = args.integer("--level", 1, 1, kMaxLevel);
  args.integer("--lod", -1, 0, args.has("--level") ? asked_level : projects ? kMaxLevel : kDefaultViewLevelMax);
  // Every input is read and checked before the display (bad input: exit 2),
  // and the display before the import notes, so that without one its line
  // comes alone (exit 3).
  std::vector<MeshOrProject> inputs;
  for (const std::string& path : paths)
    inputs.push_back(open_mesh_or_project(path, import_options(args), false));
  const MeshOrProject& input = inputs.front();
  const BaseMesh& mesh = input.mesh();
  const int level = scene_level(args, inputs, script.level > 0 ? script.level : default_view_level(inputs));
  check_edit_levels(script, level);
  const int lod = args.integer("--lod", -1, 0, level); // absent: automatic
  require_display(); // VTK aborts without one
  for (const MeshOrProject& in : inputs)
    if (!in.project)
      report_import(in.path, in.loaded);

  // The flags, else the studio's preferences (a saved device gone since is passed over with a warning).
  const studio::DeviceChoice saved = studio::preferred_device();
  std::string device = args.value("--device"), storage = args.value("--storage");
  std::shared_ptr<Runtime> runtime;
  if (!args.has("--device") && !saved.device.empty()) {
    try {
      runtime = Runtime::open(saved.device);
      device = saved.device;
    } catch (const std::exception& e) {
      std::cerr << "meshpaint view: warning: the preferred device '" << saved.device << "' cannot be opened ("
                << e.what() << "); using the default\n";
    }
  }
  if (!runtime)
    runtime = open_device(args); // reports a bad --device like every command
  if (!args.has("--storage") && (saved.storage == "buffer" || saved.storage == "image"))
    storage = saved.storage;
  vtkNew<vtkPaintView> view;
  view->SetLevel(level);
  view->SetLodLevel(lod);
  view->SetDevice(device.c_str());
  view->SetStorage(storage.c_str());
  view->SetSaveDirectory(args.value("-o", mesh.name + "-session").c_str());
  view->SetSize(picture.width, picture.height);
  if (input.project) { // the project's surface as saved, painted on from here
    const AtlasStorage chosen = storage.empty() ? default_storage(runtime->info()) : parse_storage(storage);
    view->SetSurface(open_paint_surface(runtime, chosen, input, level), mesh.name);
    view->SetProject(*input.project);
  } else {
    for (const MeshOrProject& in : inputs)
      if (!view->AddBaseMesh(in.mesh()))
        throw DeviceError(view->GetLastError());
  }
  if (args.has("--labels")) // the file's classes replace the mesh's or the project's, as in paint
    view->SetLabelClasses(new_labels);
  if (!script.strokes.empty() && !view->ApplyScript(script))
    throw DeviceError(view->GetLastError()); // the script was checked: what fails now is the device
  std::string names;
  for (int k = 0; k < view->GetNumberOfObjects(); ++k)
    names += (k ? ", " : "") + std::string(view->GetObjectName(k));
  std::cout << "view       " << names << " at level " << level << "; h in the window lists the keys; saves go to "
            << view->GetSaveDirectory() << "/" << std::endl;
  return studio::run_studio(view);
}

} // namespace meshpaint::cli
