// meshpaint fit: a scan turned into a project: a coarse base mesh, an atlas
// whose finest limit surface lies on the scan, and the fit error.

#include "commands.h"
#include "progress_bar.h"
#include "table.h"

#include "VtkSurfaceQuery.h"

#include "core/errors.h"
#include "core/file_lock.h"
#include "core/format.h"
#include "core/timer.h"
#include "mesh/decimate.h"
#include "project/project_surface.h"
#include "project/scan_fit.h"

#include <iostream> // for std::cout, std::cerr
#include <sstream>  // for std::ostringstream

namespace meshpaint::cli {
namespace {

std::string error_text(const FitError& e, double diagonal)
{
  std::ostringstream os;
  os.precision(4);
  os << "RMS " << e.rms << " (" << format_fixed(100 * e.rms / diagonal, 4) << "%), max " << e.max << " ("
     << format_fixed(100 * e.max / diagonal, 4) << "%)";
  return os.str();
}

//! "3 patches fold: 12 near (x, y, z), ..." for a warning line (first five).
std::string patch_list(const std::vector<int>& patches, const Atlas& atlas, const std::vector<Float4>& limit)
{
  const LevelLayout l = atlas.layout(atlas.max_level());
  std::string out;
  for (std::size_t k = 0; k < patches.size() && k < 5; ++k) {
    const Float4& c = limit[l.index(patches[k], l.n / 2, l.n / 2)];
    std::ostringstream os;
    os.precision(4);
    os << patches[k] << " near (" << c[0] << ", " << c[1] << ", " << c[2] << ")";
    out += (k ? ", " : "") + os.str();
  }
  return out + (patches.size() > 5 ? ", ..." : "");
}

} // namespace

int fit_command(const Argv& argv)
{
  Args args("fit", argv, {"--direct", "--quiet", "--no-weld"}, {"--base-faces", "--level", "--passes", "-o", "--device", "--storage"});
  args.expect_positionals(1, 1, "SCAN [--base-faces N] [--level L] [--direct] -o PROJECT.meshpaint");
  const std::string out = args.value("-o");
  if (out.empty())
    throw InputError("-o PROJECT.meshpaint is required");
  if (!is_project_path(out))
    throw InputError("-o needs a file name ending in .meshpaint, not '" + out + "'");
  check_output_folder(out);
  if (args.flag("--direct") && args.has("--base-faces"))
    throw InputError("--base-faces and --direct exclude each other");
  const int base_faces = args.integer("--base-faces", 0, 4, 10000000);
  const int level = args.integer("--level", 3, 1, kMaxLevel);
  const int passes = args.integer("--passes", 2, 1, 100);
  ProgressBar bar("meshpaint fit", args.flag("--quiet"));
  const auto say = [&](const std::string& line) { bar.note(line); };

  Timer total, t;
  const std::string path = args.positionals()[0];
  const BaseMesh scan = load_reported(path, import_options(args));
  const ScanReference scan_file = scan_reference(path);
  say("read " + path + ": " + grouped(scan.vertex_count()) + " vertices, " + grouped(scan.face_count()) +
      " faces (" + format_fixed(t.ms(), 0) + " ms)");
  t.restart();
  std::string mode;
  BaseMesh base;
  if (args.flag("--direct")) {
    base = scan;
    mode = "direct: the scan is the base mesh";
  } else {
    const std::size_t budget = base_faces > 0 ? std::size_t(base_faces) : default_base_faces(scan.face_count());
    say("decimating to " + grouped(budget) + " faces");
    base = decimate(scan, budget);
    mode = "decimated to " + grouped(base.face_count()) + " faces (budget " + grouped(budget) + ")";
  }
  const double decimate_ms = t.ms();
  say(mode + " (" + format_fixed(decimate_ms, 0) + " ms)");

  auto runtime = open_device(args);
  t.restart();
  PaintSurface surface(runtime, base, level, chosen_storage(args, *runtime));
  surface.undo_log().set_recording(false);
  say("atlas: level " + std::to_string(level) + ", " + grouped(surface.atlas().topology().patch_count) +
      " patches (" + format_fixed(t.ms(), 0) + " ms)");
  t.restart();
  FitOptions options;
  options.passes = passes;
  options.progress = &bar;
  const FitReport fit = fit_atlas(surface.atlas(), scan, vtk_surface_queries(), options);
  surface.geometry_changed();
  const double fit_ms = t.ms();

  Project project;
  project.scan = scan_file;
  capture_surface(surface, project);
  project.reference = project.positions;
  t.restart();
  {
    const FileLock turn(out, nullptr); // as every project save: one run at a time replaces it
    save_project(project, out);
  }
  const double save_ms = t.ms();

  const double diagonal = fit.diagonal;
  std::cout << "scan       " << path << ": " << grouped(scan.vertex_count()) << " vertices, "
            << grouped(scan.face_count()) << " faces, diagonal " << diagonal << "\n";
  std::cout << "base mesh  " << mode << "\n";
  std::cout << "atlas      level " << level << ", " << grouped(surface.atlas().topology().patch_count) << " patches, "
            << grouped(fit.points) << " points fitted in " << passes << " passes, " << grouped(fit.ray_misses)
            << " by closest point\n";
  std::cout << "scan->fit  " << error_text(fit.scan_to_surface, diagonal) << "\n";
  std::cout << "fit->scan  " << error_text(fit.surface_to_scan, diagonal) << "\n";
  std::cout << "time       decimate " << format_fixed(decimate_ms, 0) << " ms, fit " << format_fixed(fit_ms, 0)
            << " ms, save " << format_fixed(save_ms, 0) << " ms, total " << format_fixed(total.ms(), 0) << " ms\n";
  std::cout << "saved      " << out << "\n";
  const std::vector<Float4> limit = surface.atlas().read_limit_positions();
  if (!fit.folded.empty())
    std::cerr << "meshpaint fit: warning: " << fit.folded.size() << " patches fold (a quad faces against the "
              << "surface normal): " << patch_list(fit.folded, surface.atlas(), limit) << "\n";
  if (!fit.stretched.empty())
    std::cerr << "meshpaint fit: warning: " << fit.stretched.size() << " patches stretch or shrink more than 4 "
              << "times in area: " << patch_list(fit.stretched, surface.atlas(), limit) << "\n";
  return 0;
}

} // namespace meshpaint::cli
