// meshpaint paint: a stroke script applied headless to a mesh or a project,
// the painted surface written with its channels, and the project saved.

#include "commands.h"
#include "picture_options.h"
#include "table.h"

#include "PaintingExport.h"
#include "RasterIO.h"
#include "SurfaceConversion.h"
#include "SurfaceRendering.h"

#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "project/project_surface.h"

#include <iostream> // for std::cout, std::cerr

namespace meshpaint::cli {

void paint_job(PaintSurface& surface, const std::string& name, const StrokeScript& script, int model_level,
               const std::string& dir, bool quiet, int lod)
{
  surface.undo_log().set_recording(false); // a script never undoes: no snapshots to pay for
  Table table({"stroke", "tool", "dabs", "on surface", "patches", "ms", "note"});
  Timer progress;
  for (std::size_t k = 0; k < script.strokes.size(); ++k) {
    const Stroke& stroke = script.strokes[k];
    const StrokeReport r = surface.apply(stroke);
    std::string note = r.left_surface ? "left the surface" : "";
    if (r.stretch >= kUndersampledStretch) {
      note += std::string(note.empty() ? "" : "; ") + "stretched " + format_fixed(r.stretch, 1) + "x";
      std::cerr << "warning: stroke " << k << ": edit level " << stroke.edit_level
                << " undersamples the surface here (a patch stretched " << format_fixed(r.stretch, 1)
                << " times); edit at a finer level\n";
    }
    table.add({std::to_string(k), tool_name(stroke.tool), std::to_string(r.dabs), std::to_string(r.dabs_applied),
               grouped(r.patches_touched), format_fixed(r.ms, 2), note});
    if (!quiet && progress.ms() > 1000.0) {
      std::cerr << "meshpaint paint: stroke " << k + 1 << " of " << script.strokes.size() << "\n";
      progress.restart();
    }
  }
  std::cout << "painted    " << name << " at level " << surface.level() << ", " << script.strokes.size()
            << " strokes\n";
  if (!script.strokes.empty())
    table.print(std::cout);
  if (dir.empty())
    return;
  const PaintingExportReport written = export_painting(surface, model_level, dir);
  std::cout << "wrote      " << written.surface_path << ", " << dir << "/model.obj (level " << model_level << ", "
            << written.model_quads << " quads) with model.mtl and " << written.map_width << "x"
            << written.map_height << " texture maps\n";
  if (lod > 0 && lod < surface.level()) {
    const std::string lod_out = dir + "/surface_lod" + std::to_string(lod) + ".vtp";
    write_vtp(to_polydata(surface.painted_surface(lod)), lod_out);
    std::cout << "wrote      " << lod_out << " (level " << lod << " with the normals of level " << surface.level()
              << ")\n";
  }
}

int paint_command(const Argv& argv)
{
  Args args("paint", argv, {"--quiet", "--two-sided"},
            {"--strokes", "--level", "--model-level", "--lod", "-o", "--save", "--labels", "--device", "--storage",
             "--screenshot", "--camera", "--size"});
  args.expect_positionals(1, 1, "MESH|PROJECT --strokes S.json [--level L] [--model-level M] [--lod L] [--two-sided] "
                                "[-o OUTDIR] [--save P.meshpaint] [--labels labels.json] "
                                "[--screenshot OUT.png [--camera AZ,EL,ZOOM] [--size WxH]]");
  const std::string dir = args.value("-o");
  const std::string save = args.value("--save");
  if (dir.empty() && save.empty())
    throw InputError("-o OUTDIR or --save P.meshpaint is required");
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
  const MeshOrProject input = open_mesh_or_project(args.positionals()[0]);
  const int level = input_level(args, input, script.level > 0 ? script.level : 3);
  const int model_level = args.integer("--model-level", std::max(1, level - 2), 1, level);
  const int lod = args.integer("--lod", level, 1, level);
  for (std::size_t k = 0; k < script.strokes.size(); ++k)
    if (script.strokes[k].edit_level > level)
      throw InputError("stroke " + std::to_string(k) + ": \"edit_level\" " +
                       std::to_string(script.strokes[k].edit_level) + " is finer than the painting level " +
                       std::to_string(level));
  const PictureOptions picture = picture_options(args);
  const std::string screenshot = args.value("--screenshot");
  if (args.has("--screenshot") && lower_extension(screenshot) != ".png")
    throw InputError("--screenshot must name a .png file, not '" + screenshot + "'");
  if (!args.has("--screenshot") && (args.has("--camera") || args.has("--size")))
    throw InputError("--camera and --size need --screenshot OUT.png");
  auto runtime = open_device(args);
  Timer setup;
  const auto surface = open_paint_surface(runtime, chosen_storage(args, *runtime), input, level);
  if (!args.flag("--quiet"))
    std::cerr << "meshpaint paint: surface ready in " << format_fixed(setup.ms(), 1) << " ms\n";
  if (args.flag("--two-sided"))
    surface->set_two_sided(true);
  paint_job(*surface, input.mesh().name, script, model_level, dir, args.flag("--quiet"), lod);
  if (!screenshot.empty()) {
    render_screenshot(to_polydata(surface->painted_surface()), picture.camera, picture.width, picture.height,
                      screenshot);
    std::cout << "wrote      " << screenshot << " (" << picture.width << "x" << picture.height << ")\n";
  }
  if (save.empty())
    return 0;
  Project project = input.project ? *input.project : Project();
  if (args.has("--labels"))
    project.labels = new_labels;
  project.history = continued_history(project.history, surface->history(), level);
  capture_surface(*surface, project);
  save_project(project, save);
  std::cout << "saved      " << save << " (level " << level << ", " << project.labels.size() << " labels)\n";
  return 0;
}

} // namespace meshpaint::cli
