// meshpaint fit: a scan turned into a project: a coarse base mesh, an atlas
// whose finest limit surface lies on the scan, and the fit error.

#include "commands.h"
#include "progress_bar.h"
#include "table.h"

#include "project/aabb_surface_query.h" // for meshpaint::aabb_surface_queries

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/file_lock.h"
#include "core/format.h"
#include "core/host_memory.h"
#include "core/timer.h"
#include "mesh/decimate.h"
#include "mesh/file_census.h"
#include "project/fit_memory.h"
#include "project/project_surface.h"
#include "project/scan_fit.h"

#include <nlohmann/json.hpp> // for nlohmann::json

#include <algorithm> // for std::min
#include <future>   // for std::async
#include <iostream> // for std::cout, std::cerr
#include <optional> // for std::optional
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

//! The error the fit aims for, % of the scan's diagonal, scan->fit.
constexpr double kRmsBoundPercent = 0.05;
constexpr double kMaxBoundPercent = 0.5;

//! A warning line when scan->fit misses a bound: by how much, where the
//! worst scan point lies, and a finer level or a larger base (up to the
//! scan's own `scan_triangles`) to try.
std::string bounds_warning(const FitError& e, double diagonal, int level, std::size_t base_faces,
                           std::size_t scan_triangles)
{
  const double rms = 100 * e.rms / diagonal, max = 100 * e.max / diagonal;
  if (rms <= kRmsBoundPercent && max <= kMaxBoundPercent)
    return "";
  std::ostringstream os;
  os.precision(4);
  os << "meshpaint fit: warning: the fit misses its bounds (scan->fit RMS " << format_fixed(kRmsBoundPercent, 2)
     << "%, max " << format_fixed(kMaxBoundPercent, 1) << "% of the diagonal): RMS " << format_fixed(rms, 4) << "%";
  if (rms > kRmsBoundPercent)
    os << " (" << format_fixed(rms - kRmsBoundPercent, 4) << "% over)";
  os << ", max " << format_fixed(max, 4) << "%";
  if (max > kMaxBoundPercent)
    os << " (" << format_fixed(max - kMaxBoundPercent, 4) << "% over)";
  os << " at the scan point (" << e.worst[0] << ", " << e.worst[1] << ", " << e.worst[2] << "); ";
  std::vector<std::string> tries;
  if (level < kMaxLevel)
    tries.push_back("--level " + std::to_string(level + 1));
  if (base_faces < scan_triangles)
    tries.push_back("--base-faces " + std::to_string(std::min(2 * base_faces, scan_triangles)));
  if (tries.empty())
    os << "no finer level and no larger base mesh is left to try";
  else
    os << "try " << tries[0] << (tries.size() > 1 ? " or " + tries[1] : "");
  return os.str();
}

nlohmann::json error_json(const FitError& e, double diagonal)
{
  return {{"rms", e.rms}, {"max", e.max}, {"rms_percent", 100 * e.rms / diagonal}, {"max_percent", 100 * e.max / diagonal}};
}

} // namespace

int fit_command(const Argv& argv)
{
  Args args("fit", argv, {"--direct", "--quiet", "--no-weld"}, {"--base-faces", "--level", "--passes", "-o", "--report", "--device", "--storage"});
  args.expect_positionals(1, 1, "SCAN [--base-faces N] [--level L] [--direct] [--report FILE.json] -o PROJECT.meshpaint");
  const std::string out = args.value("-o");
  if (out.empty())
    throw InputError("-o PROJECT.meshpaint is required");
  if (!is_project_path(out))
    throw InputError("-o needs a file name ending in .meshpaint, not '" + out + "'");
  check_output_folder(out);
  const std::string report_path = args.value("--report");
  if (args.has("--report")) {
    if (lower_extension(report_path) != ".json")
      throw InputError("--report needs a file name ending in .json, not '" + report_path + "'");
    check_output_folder(report_path);
  }
  if (args.flag("--direct") && args.has("--base-faces"))
    throw InputError("--base-faces and --direct exclude each other");
  const int base_faces = args.integer("--base-faces", 0, 4, 10000000);
  const int level = args.integer("--level", 3, 1, kMaxLevel);
  const int passes = args.integer("--passes", 2, 1, 100);
  ProgressBar bar("meshpaint fit", args.flag("--quiet"));
  const auto say = [&](const std::string& line) { bar.note(line); };

  Timer total, t;
  const std::string path = args.positionals()[0];
  const std::size_t available = available_host_memory(); // its setting checked before the scan is read
  const auto budget_for = [&](std::size_t faces) {
    return base_faces > 0 ? std::size_t(base_faces) : default_base_faces(faces);
  };
  const auto refuse_beyond = [&](const FitMemory& plan, const std::string& triangles) {
    if (available > 0 && plan.bytes > available)
      throw ResourceError("a fit of " + triangles + " at level " + std::to_string(level) + " needs about " +
                          format_bytes(plan.bytes) + " of memory, and " + format_bytes(available) +
                          " is available (meshpaint info " + path + " --level L plans other levels)");
  };
  // Where the file's header states its faces (each at least a triangle), a
  // scan far beyond the memory is refused before it is read.
  if (const long declared = header_face_count(path, lower_extension(path)); declared > 0) {
    const std::size_t faces = std::size_t(declared);
    refuse_beyond(plan_fit_memory(faces, args.flag("--direct") ? faces : budget_for(faces), level),
                  "at least " + counted(faces, "triangle", "triangles", true));
  }
  const BaseMesh scan = load_reported(path, import_options(args));
  const ScanReference scan_file = scan_reference(path);
  say("read " + path + ": " + grouped(scan.vertex_count()) + " vertices, " + grouped(scan.face_count()) +
      " faces (" + format_fixed(t.ms(), 0) + " ms)");
  // What the fit will take, planned before its large allocations (the
  // decimation's mesh, the scan's index, the atlas): refused, not swapped.
  const std::size_t triangles = scan.triangle_count();
  const std::size_t budget = budget_for(scan.face_count());
  refuse_beyond(plan_fit_memory(triangles, args.flag("--direct") ? triangles : budget, level),
                counted(triangles, "triangle", "triangles", true));
  t.restart();
  // The scan's index for the fit's queries does not depend on the base
  // mesh: it is built on another core while the scan is decimated (the
  // decimation runs on one).
  say("indexing the scan: " + grouped(scan.face_count()) + " faces");
  std::future<std::unique_ptr<SurfaceQuery>> scan_index =
      std::async(std::launch::async, [&scan] { return aabb_surface_queries()(scan.points, triangles_of(scan)); });
  std::string mode;
  BaseMesh base;
  std::optional<Decimation> decimation;
  if (args.flag("--direct")) {
    base = scan;
    mode = "direct: the scan is the base mesh";
  } else {
    say("decimating to " + grouped(budget) + " faces");
    decimation = decimate(scan, budget);
    if (decimation->passes.passes > 0)
      say("quadric passes: " + std::to_string(decimation->passes.passes) + " reduced the scan to " +
          grouped(decimation->passes.faces) + " faces");
    base = decimation->base;
    mode = "decimated to " + grouped(base.face_count()) + " faces (budget " + grouped(budget) + ")";
    for (int s = 0; s + 1 < decimation->stages; ++s)
      say("decimation stage " + std::to_string(s + 1) + " stopped at " + grouped(decimation->stage_faces[s]) +
          " faces; stage " + std::to_string(s + 2) + " goes on");
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
  const std::unique_ptr<SurfaceQuery> scan_query = scan_index.get();
  options.scan_query = scan_query.get();
  const FitReport fit = fit_atlas(surface.atlas(), scan, aabb_surface_queries(), options);
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
  std::cout << "scan       " << path << ": " << counted(scan.vertex_count(), "vertex", "vertices", true) << ", "
            << counted(scan.face_count(), "face", "faces", true) << ", diagonal " << diagonal << "\n";
  std::cout << "base mesh  " << mode << "\n";
  std::cout << "atlas      level " << level << ", " << grouped(surface.atlas().topology().patch_count) << " patches, "
            << grouped(fit.points) << " points fitted in " << passes << " passes, " << grouped(fit.ray_misses)
            << " by closest point\n";
  std::cout << "scan->fit  " << error_text(fit.scan_to_surface, diagonal) << "\n";
  std::cout << "fit->scan  " << error_text(fit.surface_to_scan, diagonal) << "\n";
  std::cout << "time       decimate " << format_fixed(decimate_ms, 0) << " ms, fit " << format_fixed(fit_ms, 0)
            << " ms, save " << format_fixed(save_ms, 0) << " ms, total " << format_fixed(total.ms(), 0) << " ms\n";
  std::cout << "saved      " << out << "\n";
  if (!report_path.empty()) {
    // One report, written only when the project is: a batch reads both.
    nlohmann::json stage_faces = nlohmann::json::array();
    for (int k = 0; decimation && k < decimation->stages; ++k)
      stage_faces.push_back(decimation->stage_faces[k]);
    nlohmann::json j = {{"scan", path},
                        {"scan_vertices", scan.vertex_count()},
                        {"scan_faces", scan.face_count()},
                        {"diagonal", diagonal},
                        {"mode", decimation ? "decimated" : "direct"},
                        {"base_faces", base.face_count()},
                        {"budget", decimation ? nlohmann::json(decimation->budget) : nlohmann::json(nullptr)},
                        {"decimation_stages", decimation ? decimation->stages : 0},
                        {"decimation_stage_faces", stage_faces},
                        {"quadric_passes", decimation ? decimation->passes.passes : 0},
                        {"quadric_pass_faces", decimation && decimation->passes.passes > 0
                                                   ? nlohmann::json(decimation->passes.faces)
                                                   : nlohmann::json(nullptr)},
                        {"level", level},
                        {"patches", surface.atlas().topology().patch_count},
                        {"points", fit.points},
                        {"passes", passes},
                        {"ray_misses", fit.ray_misses},
                        {"scan_to_fit", error_json(fit.scan_to_surface, diagonal)},
                        {"fit_to_scan", error_json(fit.surface_to_scan, diagonal)},
                        {"folded_patches", fit.folded.size()},
                        {"stretched_patches", fit.stretched.size()},
                        {"decimate_s", decimate_ms / 1000},
                        {"fit_s", fit_ms / 1000},
                        {"save_s", save_ms / 1000},
                        {"total_s", total.ms() / 1000},
                        {"project", out}};
    // Paths need not be UTF-8: such bytes become U+FFFD rather than an exception.
    const std::string text = j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    write_bytes_atomically(report_path, {text});
    std::cout << "report     " << report_path << "\n";
  }
  const std::string missed = bounds_warning(fit.scan_to_surface, diagonal, level, triangles_of(base).size(),
                                             triangles_of(scan).size());
  if (!missed.empty())
    std::cerr << missed << "\n";
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
