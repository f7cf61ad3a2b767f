// meshpaint paint: a stroke script applied headless, the painted surface
// written with its channels.

#include "commands.h"
#include "table.h"

#include "RasterIO.h"
#include "SurfaceConversion.h"

#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "paint/model_export.h"
#include "paint/paint_surface.h"

#include <filesystem> // for std::filesystem
#include <iostream>   // for std::cout, std::cerr

namespace meshpaint::cli {
void paint_job(const std::shared_ptr<Runtime>& runtime, AtlasStorage storage, const BaseMesh& mesh,
               const StrokeScript& script, int level, int model_level, const std::string& dir, bool quiet, int lod)
{
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw IOError("cannot create '" + dir + "': " + ec.message());
  Timer total;
  PaintSurface surface(runtime, mesh, level, storage);
  surface.undo_log().set_recording(false); // a script never undoes: no snapshots to pay for
  const double setup_ms = total.ms();
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
  const std::string out = dir + "/surface.vtp";
  write_vtp(to_polydata(surface.painted_surface()), out);
  ExportModel model;
  TextureMaps maps;
  build_export(surface, model_level, model, maps);
  write_texture_maps(maps, dir);
  write_obj_model(model, maps, dir);
  if (lod > 0 && lod < level) {
    const std::string lod_out = dir + "/surface_lod" + std::to_string(lod) + ".vtp";
    write_vtp(to_polydata(surface.painted_surface(lod)), lod_out);
    std::cout << "wrote      " << lod_out << " (level " << lod << " with the normals of level " << level << ")\n";
  }
  std::cout << "painted    " << mesh.name << " at level " << level << ", " << script.strokes.size()
            << " strokes (set-up " << format_fixed(setup_ms, 1) << " ms)\n";
  table.print(std::cout);
  std::cout << "wrote      " << out << ", " << dir << "/model.obj (level " << model_level << ", "
            << model.mesh.quads.size() << " quads) with model.mtl and " << maps.width << "x" << maps.height
            << " texture maps\n";
}

int paint_command(const Argv& argv)
{
  Args args("paint", argv, {"--quiet"},
            {"--strokes", "--level", "--model-level", "--lod", "-o", "--device", "--storage"});
  args.expect_positionals(1, 1, "MESH --strokes S.json [--level L] [--model-level M] [--lod L] -o OUTDIR");
  if (!args.has("--strokes"))
    throw InputError("--strokes S.json is required");
  const std::string dir = args.value("-o");
  if (dir.empty())
    throw InputError("-o OUTDIR is required");
  // Everything is checked before anything is painted.
  StrokeScript script = load_stroke_script(args.value("--strokes"));
  load_stroke_rasters(script);
  const int level = args.integer("--level", script.level > 0 ? script.level : 3, 1, kMaxLevel);
  const int model_level = args.integer("--model-level", std::max(1, level - 2), 1, level);
  const int lod = args.integer("--lod", level, 1, level);
  for (std::size_t k = 0; k < script.strokes.size(); ++k)
    if (script.strokes[k].edit_level > level)
      throw InputError("stroke " + std::to_string(k) + ": \"edit_level\" " +
                       std::to_string(script.strokes[k].edit_level) + " is finer than the painting level " +
                       std::to_string(level));
  const BaseMesh mesh = load_reported(args.positionals()[0]);
  auto runtime = open_device(args);
  paint_job(runtime, args.has("--storage") ? parse_storage(args.value("--storage")) : default_storage(runtime->info()),
            mesh, script, level, model_level, dir, args.flag("--quiet"), lod);
  return 0;
}

} // namespace meshpaint::cli
