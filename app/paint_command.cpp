// meshpaint paint: a stroke script applied headless to a mesh or a project,
// the painted surface written with its channels, and the project saved.

#include "commands.h"
#include "picture_options.h"
#include "progress_bar.h"
#include "table.h"

#include "ChannelDisplay.h"
#include "DisplayCheck.h"
#include "PaintingExport.h"
#include "RasterIO.h"
#include "SurfaceConversion.h"
#include "SurfaceRendering.h"

#include "core/errors.h"
#include "core/file_lock.h"
#include "core/format.h"
#include "core/timer.h"
#include "project/imported_labels.h"
#include "project/project_surface.h"

#include "paint/paint_scene.h"
#include "paint/stroke_session.h"

#include <vtkAppendPolyData.h> // for vtkAppendPolyData

#include <algorithm> // for std::max
#include <iostream>  // for std::cout, std::cerr
#include <optional>  // for std::optional

namespace meshpaint::cli {

void paint_job(PaintScene& scene, const StrokeScript& script, int model_level, const std::string& dir, bool quiet,
               int lod, const std::vector<LabelClass>& labels)
{
  std::string names;
  for (std::size_t o = 0; o < scene.size(); ++o) {
    scene.surface(o).undo_log().set_recording(false); // a script never undoes: no snapshots to pay for
    names += (o ? ", " : "") + scene.name(o);
  }
  Table table({"stroke", "tool", "dabs", "on surface", "patches", "ms", "note"});
  StrokeSession session(scene);
  ProgressBar bar("meshpaint paint", quiet);
  std::optional<ProgressTask> painting;
  if (!script.strokes.empty())
    painting.emplace(&bar, "painting " + std::to_string(script.strokes.size()) + " strokes", script.strokes.size());
  for (std::size_t k = 0; k < script.strokes.size(); ++k) {
    const Stroke& stroke = script.strokes[k];
    // A scene's stroke: its dabs over every object, its time the sum.
    StrokeReport r;
    std::vector<StrokeReport> reports;
    try {
      reports = session.apply(stroke);
    } catch (const InputError& e) {
      throw InputError("stroke " + std::to_string(k) + ": " + e.what());
    }
    for (const StrokeReport& o : reports) {
      r.dabs = std::max(r.dabs, o.dabs);
      r.dabs_applied += o.dabs_applied;
      r.patches_touched += o.patches_touched;
      r.ms += o.ms;
      r.left_surface = r.left_surface || o.left_surface;
      r.stretch = std::max(r.stretch, o.stretch);
    }
    std::string note = r.left_surface ? "left the surface" : "";
    if (r.stretch >= kUndersampledStretch) {
      note += std::string(note.empty() ? "" : "; ") + "stretched " + format_fixed(r.stretch, 1) + "x";
      bar.print("warning: stroke " + std::to_string(k) + ": edit level " + std::to_string(stroke.edit_level()) +
                " undersamples the surface here (a patch stretched " + format_fixed(r.stretch, 1) +
                " times); edit at a finer level");
    }
    table.add({std::to_string(k), tool_name(stroke.tool), std::to_string(r.dabs), std::to_string(r.dabs_applied),
               grouped(r.patches_touched), format_fixed(r.ms, 2), note});
    painting->step(k + 1);
  }
  painting.reset();
  std::cout << "painted    " << names << " at level " << scene.surface(0).level() << ", " << script.strokes.size()
            << " strokes\n";
  if (!script.strokes.empty())
    table.print(std::cout);
  if (dir.empty())
    return;
  for (std::size_t o = 0; o < scene.size(); ++o) {
    PaintSurface& surface = scene.surface(o);
    const std::string out = scene.folder(dir, o);
    const PaintingExportReport written = export_painting(surface, model_level, out, labels, &bar);
    std::cout << "wrote      " << written.surface_path << ", " << out << "/model.obj (level " << model_level << ", "
              << written.model_quads << " quads) with model.mtl, model.gltf and " << written.map_width << "x"
              << written.map_height << " texture maps\n";
    if (lod > 0 && lod < surface.level()) {
      const std::string lod_out = out + "/surface_lod" + std::to_string(lod) + ".vtp";
      write_vtp(to_polydata(surface.painted_surface(lod)), lod_out);
      std::cout << "wrote      " << lod_out << " (level " << lod << " with the normals of level "
                << surface.level() << ")\n";
    }
  }
}

int paint_command(const Argv& argv)
{
  Args args("paint", argv, {"--quiet", "--two-sided", "--no-weld"},
            {"--strokes", "--level", "--model-level", "--lod", "-o", "--save", "--labels", "--device", "--storage",
             "--screenshot", "--camera", "--size", "--subsurface", "--gltf", "--show", "--import-array"});
  args.expect_positionals(1, 64, "MESH|PROJECT... --strokes S.json [--level L] [--model-level M] [--lod L] [--two-sided] "
                                "[-o OUTDIR] [--gltf FILE.glb|FILE.gltf] [--save P.meshpaint] [--labels labels.json] "
                                "[--screenshot OUT.png [--camera AZ,EL,ZOOM] [--size WxH] [--subsurface N] "
                                "[--show label|diffuse|specular|roughness|displacement|mask]]");
  const std::string dir = args.value("-o");
  const std::string save = args.value("--save");
  const std::string gltf = args.value("--gltf");
  if (dir.empty() && save.empty() && gltf.empty())
    throw InputError("-o OUTDIR, --gltf FILE or --save P.meshpaint is required");
  if (args.has("--gltf") && lower_extension(gltf) != ".glb" && lower_extension(gltf) != ".gltf")
    throw InputError("--gltf must name a .glb or .gltf file, not '" + gltf + "'");
  if (!save.empty() && !is_project_path(save))
    throw InputError("--save needs a file name ending in .meshpaint, not '" + save + "'");
  if (!args.has("--strokes") && save.empty())
    throw InputError("--strokes S.json is required");
  // Everything is checked before anything is painted.
  StrokeScript script;
  if (args.has("--strokes")) {
    script = load_stroke_script(args.value("--strokes"));
    load_stroke_rasters(script);
  }
  const std::vector<LabelClass> new_labels =
    args.has("--labels") ? load_labels(args.value("--labels")) : std::vector<LabelClass>();
  const std::vector<std::string>& paths = args.positionals();
  if (paths.size() > 1 && !save.empty())
    throw InputError("--save keeps one surface: give one MESH or PROJECT, not " + std::to_string(paths.size()));
  if (paths.size() > 1 && !gltf.empty())
    throw InputError("--gltf keeps one surface: give one MESH or PROJECT, not " + std::to_string(paths.size()));
  // Runs continuing one project take turns from reading it to saving it, so
  // none saves over strokes another added meanwhile.
  const FileLock turn(save, [&] {
    if (!args.flag("--quiet"))
      std::cerr << "meshpaint paint: waiting for another meshpaint to finish with " << save << "\n";
  });
  std::vector<MeshOrProject> inputs;
  for (const std::string& path : paths)
    inputs.push_back(open_mesh_or_project(path, import_options(args)));
  const MeshOrProject& input = inputs.front();
  const int level = scene_level(args, inputs, script.level > 0 ? script.level : 3);
  const int model_level = args.integer("--model-level", default_model_level(level), 1, level);
  const int lod = args.integer("--lod", level, 1, level);
  check_edit_levels(script, level);
  const PictureOptions picture = picture_options(args);
  const std::string screenshot = args.value("--screenshot");
  if (args.has("--screenshot") && lower_extension(screenshot) != ".png")
    throw InputError("--screenshot must name a .png file, not '" + screenshot + "'");
  if (!args.has("--screenshot") &&
      (args.has("--camera") || args.has("--size") || args.has("--subsurface") || args.has("--show")))
    throw InputError("--camera, --size, --subsurface and --show need --screenshot OUT.png");
  const int subsurface = args.integer("--subsurface", 0, 0, 10000);
  const ShownChannel shown = parse_shown_channel(args.value("--show", "diffuse"));
  if (shown != ShownChannel::diffuse && subsurface > 0)
    throw InputError("--subsurface lights the diffuse colour: it does not go with --show " + args.value("--show"));
  if (!screenshot.empty())
    require_display(); // before the painting, which may take long
  auto runtime = open_device(args);
  Timer setup;
  PaintScene scene;
  for (const MeshOrProject& in : inputs) {
    auto surface = open_paint_surface(runtime, chosen_storage(args, *runtime), in, level);
    if (args.flag("--two-sided"))
      surface->set_two_sided(true);
    scene.add(std::move(surface), in.mesh().name);
  }
  if (!args.flag("--quiet"))
    std::cerr << "meshpaint paint: " << (inputs.size() == 1 ? "surface" : "surfaces") << " ready in "
              << format_fixed(setup.ms(), 1) << " ms\n";
  // A mesh file's own label ids come with a class each, unless --labels names them.
  const std::vector<LabelClass> imported = imported_label_classes(input.mesh());
  const std::vector<LabelClass>& classes =
    args.has("--labels") ? new_labels : input.project ? input.project->labels : imported;
  paint_job(scene, script, model_level, dir, args.flag("--quiet"), lod, classes);
  if (!gltf.empty()) {
    export_gltf(scene.surface(0), model_level, gltf);
    std::cout << "wrote      " << gltf << " (level " << model_level << ", textures inside)\n";
  }
  if (!screenshot.empty()) {
    auto all = vtkSmartPointer<vtkAppendPolyData>::New();
    for (std::size_t o = 0; o < scene.size(); ++o) {
      vtkSmartPointer<vtkPolyData> poly = to_polydata(scene.surface(o).painted_surface());
      if (subsurface > 0) // the light from the camera, diffused over the atlas
        add_scattered_light(poly, scene.surface(o), headlight_direction(picture.camera), subsurface);
      all->AddInputData(poly);
    }
    all->Update();
    const std::vector<LabelClass>& labels =
      args.has("--labels") ? new_labels : input.project ? input.project->labels : imported;
    render_screenshot(all->GetOutput(), picture.camera, picture.width, picture.height, screenshot, shown, labels);
    std::cout << "wrote      " << screenshot << " (" << picture.width << "x" << picture.height << ")\n";
  }
  PaintSurface* const surface = &scene.surface(0);
  if (save.empty())
    return 0;
  Project project = input.project ? *input.project : Project();
  if (args.has("--labels"))
    project.labels = new_labels;
  else if (!input.project)
    project.labels = imported;
  const std::size_t labels = project.labels.size();
  save_painted_project(*surface, std::move(project), save, SaveTurn::held); // `turn` is held since reading
  std::cout << "saved      " << save << " (level " << level << ", " << labels << " labels)\n";
  return 0;
}

} // namespace meshpaint::cli
