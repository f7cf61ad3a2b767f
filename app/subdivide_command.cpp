#include "commands.h"
#include "progress_bar.h"

#include "SurfaceConversion.h"

#include "atlas/atlas.h"
#include "atlas/weld.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "mesh/surface_io.h"

#include <algorithm>  // for std::max
#include <filesystem> // for std::filesystem::path
#include <iostream>   // for std::cerr
#include <optional>   // for std::optional

namespace meshpaint::cli {

void check_surface_format(const std::string& path)
{
  const std::string ext = lower_extension(path);
  if (ext != ".obj" && ext != ".ply" && ext != ".vtp")
    throw InputError("cannot write '" + path + "': unknown format '" + ext + "' (.obj, .ply, .vtp)");
}

void write_any(const WeldedSurface& surface, const std::string& path)
{
  check_surface_format(path);
  if (lower_extension(path) == ".vtp")
    write_vtp(to_polydata(surface), path);
  else
    write_surface(surface, path);
}

int subdivide_command(const Argv& argv)
{
  Args args("subdivide", argv, {"--limit", "--quiet", "--no-weld"}, {"--level", "-o", "--device", "--storage"});
  args.expect_positionals(1, 1, "MESH|PROJECT --level L [--limit] -o OUT.{obj,ply,vtp}");
  if (!args.has("--level"))
    throw InputError("--level is required (1.." + std::to_string(kMaxLevel) + ")");
  const int level = args.integer("--level", 1, 1, kMaxLevel);
  const std::string out = args.value("-o");
  if (out.empty())
    throw InputError("-o OUT.{obj,ply,vtp} is required");
  check_surface_format(out);
  check_output_folder(out);

  Timer t;
  const MeshOrProject input = open_mesh_or_project(args.positionals()[0], import_options(args));
  // A project's surface is its painting level's control points: refined
  // from there, or reduced below it.
  const int own = input.project ? input.project->level : 1;
  if (input.project && args.flag("--limit") && level < own)
    throw InputError("--limit needs --level " + std::to_string(own) + " or more for a level-" +
                     std::to_string(own) + " project");
  const double load_ms = t.ms();
  auto runtime = open_device(args);
  ProgressBar bar("meshpaint subdivide", args.flag("--quiet"));
  // Four phases of very different lengths: enough to see which one runs.
  std::optional<ProgressTask> task;
  task.emplace(&bar, "level " + std::to_string(level) + " into " + out, 4);
  t.restart();
  Atlas atlas(runtime, input.mesh(), std::max(level, own), chosen_storage(args, *runtime));
  const double setup_ms = t.ms();
  task->step(1);
  t.restart();
  atlas.subdivide(1, own);
  if (input.project)
    atlas.write_positions(own, input.project->positions);
  if (level > own)
    atlas.subdivide(own, level);
  else if (level < own)
    atlas.reduce(own, level);
  atlas.finish();
  const double kernel_ms = t.ms();
  task->step(2);
  t.restart();
  const WeldedSurface surface = level_surface(atlas, level, args.flag("--limit"));
  const double read_ms = t.ms();
  task->step(3);
  t.restart();
  write_any(surface, out);
  task->step(4);
  task.reset();
  if (!args.flag("--quiet"))
    std::cerr << "meshpaint subdivide: " << out << ": level " << level << ", " << surface.points.size()
              << " vertices, " << surface.quads.size() << " quads; load " << format_fixed(load_ms, 1)
              << " ms, atlas " << format_fixed(setup_ms, 1) << " ms, kernels " << format_fixed(kernel_ms, 1)
              << " ms, read " << format_fixed(read_ms, 1) << " ms, write " << format_fixed(t.ms(), 1) << " ms\n";
  return 0;
}

} // namespace meshpaint::cli
