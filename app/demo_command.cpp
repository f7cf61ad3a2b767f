// meshpaint demo: the main job on a bundled scan, with timings.

#include "commands.h"
#include "progress_bar.h"

#include "SurfaceConversion.h"

#include "atlas/atlas.h"
#include "atlas/weld.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "mesh/surface_io.h"
#include "paint/stroke.h"

#include <filesystem> // for std::filesystem
#include <iostream>   // for std::cout
#include <optional>   // for std::optional, std::in_place

namespace meshpaint::cli {

int demo_command(const Argv& argv)
{
  Args args("demo", argv, {"--quiet"}, {"--level", "-o", "--device", "--storage"});
  args.expect_positionals(0, 1, "[MESH] [--level L] [-o DIR] [--quiet]");
  const std::string path = args.positionals().empty() ? scans_dir() + "/bunny00.off" : args.positionals()[0];
  const int level = args.integer("--level", 3, 1, kMaxLevel);
  const std::string dir = args.value("-o", "meshpaint-demo");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw IOError("cannot create '" + dir + "': " + ec.message());

  std::ostream& os = std::cout;
  // The subdivision's steps: load, atlas, subdivide, limit, write; then the painting's own.
  ProgressBar bar("meshpaint demo", args.flag("--quiet"));
  std::optional<ProgressTask> task(std::in_place, &bar, "subdividing " + path + " to level " + std::to_string(level), 5);
  Timer t;
  const BaseMesh mesh = load_reported(path);
  task->step(1);
  os << "loaded     " << path << ": " << mesh.vertex_count() << " vertices, " << mesh.face_count()
     << " faces (" << format_fixed(t.ms(), 1) << " ms)\n";
  auto runtime = open_device(args);
  const AtlasStorage storage = chosen_storage(args, *runtime);
  os << "device     " << runtime->info().summary() << ", " << storage_name(storage) << " storage\n";
  t.restart();
  Atlas atlas(runtime, mesh, level, storage);
  os << "atlas      " << atlas.topology().patch_count << " patches, level " << level << " tiles "
     << atlas.layout(level).tile << "x" << atlas.layout(level).tile << " (first step, tables, kernels: "
     << format_fixed(t.ms(), 1) << " ms)\n";
  task->step(2);
  t.restart();
  atlas.subdivide(1, level);
  atlas.finish();
  task->step(3);
  os << "subdivide  levels 1->" << level << " on the device: " << format_fixed(t.ms(), 1) << " ms\n";
  t.restart();
  const WeldedSurface surface = level_surface(atlas, level, true);
  os << "limit      positions and normals, read back and welded: " << surface.points.size() << " vertices, "
     << surface.quads.size() << " quads: " << format_fixed(t.ms(), 1) << " ms\n";
  task->step(4);
  t.restart();
  const std::string out = dir + "/" + mesh.name + "_level" + std::to_string(level) + "_limit.vtp";
  write_any(surface, out);
  os << "wrote      " << out << " (" << format_fixed(t.ms(), 1) << " ms)\n";
  task->step(5);
  task.reset();

  // Then the main job: painting. The bundled script's strokes lie on the
  // bunny; another mesh gets its marble wash only.
  StrokeScript script = load_stroke_script(strokes_dir() + "/bunny_demo.json");
  if (!args.positionals().empty())
    script.strokes.resize(1);
  PaintScene scene;
  scene.add(std::make_unique<PaintSurface>(runtime, mesh, level, storage), mesh.name);
  paint_job(scene, script, std::max(1, level - 2), dir + "/painted", args.flag("--quiet"));
  return 0;
}

} // namespace meshpaint::cli
