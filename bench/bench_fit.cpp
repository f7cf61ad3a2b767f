// meshpaint bench fit: `meshpaint fit` on every scan in data/scans, then
// against scan size: the femur scan refined by OpenMesh's Loop and sqrt(3)
// subdividers from 10^5 triangles to 10^7, each with seeded
// Gaussian noise. Every fit runs as the meshpaint program in a child
// process, whose wall time and peak resident memory (wait4's rusage) are
// what a user's run would take; its numbers come from its JSON report.

#include "benchmarks.h"
#include "decimation_peers.h"
#include "progress_bar.h"
#include "table.h"

#include "PolyDataFiles.h"

#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "mesh/decimate.h"

#include <nlohmann/json.hpp>                     // for nlohmann::json
#include <OpenMesh/Core/IO/MeshIO.hh>                   // for OpenMesh::IO::read_mesh, write_mesh
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>   // for TriMesh_ArrayKernelT
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>   // for LoopT
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>  // for Sqrt3T

#include <cerrno>     // for errno
#include <cstring>    // for std::strerror
#include <algorithm>  // for std::sort
#include <filesystem> // for std::filesystem
#include <fstream>    // for std::ifstream
#include <iostream>   // for std::cout
#include <optional>   // for std::optional
#include <random>     // for std::mt19937, std::normal_distribution
#include <sstream>    // for std::ostringstream
#include <utility>    // for std::pair

#include <csignal>        // for SIGKILL
#include <fcntl.h>        // for O_WRONLY
#include <spawn.h>        // for posix_spawn
#include <sys/resource.h> // for rusage
#include <sys/wait.h>     // for wait4
#include <unistd.h>       // for readlink

extern char** environ;

namespace meshpaint::cli {
namespace {

namespace fs = std::filesystem;
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

//! Noise of the made scans: per coordinate, as a fraction of the diagonal.
constexpr double kNoise = 1e-4;
//! Smallest scan measured.
constexpr std::size_t kSmallest = 100000;
// The largest of the default series: the scan of 10^7 triangles (10,106,208).
constexpr int kLargest = 10200000;
//! Runs of each decimation method; the median's time is reported.
constexpr int kDecimationRepeats = 3;
// The decimation peers of the size series stop here: above, VTK's and
// CGAL's ordered collapses take minutes each (204 s for CGAL's at 8M).
constexpr std::size_t kSeriesPeerTriangles = 2000000;

struct FitRun
{
  std::size_t triangles = 0, vertices = 0;
  double wall_s = 0, peak_mib = 0;
  std::string warnings;         //!< fit's stderr
  nlohmann::json report;        //!< fit's --report
  std::string failure;          //!< empty when the fit succeeded
};

std::string program_folder()
{
  std::string self(4096, '\0');
  const ssize_t n = readlink("/proc/self/exe", self.data(), self.size());
  if (n <= 0)
    throw ResourceError("cannot find this program's folder: " + std::string(std::strerror(errno)));
  self.resize(std::size_t(n));
  return self.substr(0, self.rfind('/') + 1);
}

std::string read_text(const fs::path& path)
{
  std::ifstream in(path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

//! Runs `argv` with stdout and stderr into files; its wall time and peak memory.
FitRun run_measured(const std::vector<std::string>& argv, const fs::path& out, const fs::path& err)
{
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> args;
  for (const std::string& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  FitRun run;
  const Timer wall;
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &files, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (spawned != 0)
    throw ResourceError("cannot run " + argv[0] + ": " + std::strerror(spawned));
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid)
    throw ResourceError("lost the fit process: " + std::string(std::strerror(errno)));
  run.wall_s = wall.ms() / 1000;
  run.peak_mib = double(usage.ru_maxrss) / 1024; // kilobytes on Linux
  run.warnings = read_text(err);
  if (WIFSIGNALED(status))
    run.failure = "killed by signal " + std::to_string(WTERMSIG(status)) +
                  (WTERMSIG(status) == SIGKILL ? " (out of memory?)" : "");
  else if (WEXITSTATUS(status) != 0) {
    const std::string text = run.warnings.substr(0, run.warnings.find('\n'));
    run.failure = "exit " + std::to_string(WEXITSTATUS(status)) + ": " + text;
  }
  return run;
}

//! Writes the mesh with noise added, as binary PLY, leaving `mesh` unchanged.
void write_noisy(TriMesh& mesh, double sigma, unsigned seed, const fs::path& path)
{
  std::vector<TriMesh::Point> clean(mesh.points(), mesh.points() + mesh.n_vertices());
  std::mt19937 random(seed);
  std::normal_distribution<float> noise(0.f, float(sigma));
  for (auto v : mesh.vertices())
    mesh.point(v) += TriMesh::Point(noise(random), noise(random), noise(random));
  const bool written = OpenMesh::IO::write_mesh(mesh, path.string(), OpenMesh::IO::Options::Binary);
  for (auto v : mesh.vertices())
    mesh.set_point(v, clean[std::size_t(v.idx())]);
  if (!written)
    throw IOError("cannot write the made scan " + path.string());
}

//! Fits `scan` with `meshpaint fit --report` in a child process.
FitRun fit_scan(const std::string& program, const fs::path& scan, int level, const std::vector<std::string>& passed,
                const fs::path& folder)
{
  const fs::path report = folder / "fit.json";
  fs::remove(report);
  std::vector<std::string> argv = {program, "fit", scan.string(), "--level", std::to_string(level), "--quiet",
                                   "--report", report.string(), "-o", (folder / "scan.meshpaint").string()};
  argv.insert(argv.end(), passed.begin(), passed.end());
  FitRun run = run_measured(argv, folder / "fit.txt", folder / "fit.err");
  if (run.failure.empty())
    run.report = nlohmann::json::parse(read_text(report));
  return run;
}

//! A stroke script for the femur's fitted projects: a label stroke and a
//! paint stroke along its length, through its vertices on the +x side (on
//! the surface of every refinement of it, to within the noise).
void write_femur_strokes(const TriMesh& femur, const fs::path& path)
{
  TriMesh::Point lo = femur.point(*femur.vertices_begin()), hi = lo;
  for (auto v : femur.vertices()) {
    lo.minimize(femur.point(v));
    hi.maximize(femur.point(v));
  }
  nlohmann::json points = nlohmann::json::array();
  constexpr int kPoints = 20;
  for (int k = 0; k < kPoints; ++k) {
    const TriMesh::Point aim(hi[0], (lo[1] + hi[1]) / 2, lo[2] + (hi[2] - lo[2]) * (k + 0.5f) / kPoints);
    TriMesh::Point nearest = femur.point(*femur.vertices_begin());
    for (auto v : femur.vertices())
      if ((femur.point(v) - aim).sqrnorm() < (nearest - aim).sqrnorm())
        nearest = femur.point(v);
    points.push_back({nearest[0], nearest[1], nearest[2]});
  }
  const double radius = 0.03 * (hi - lo).norm();
  const nlohmann::json script = {
      {"strokes",
       {{{"tool", "label"}, {"points", points}, {"radius", radius}, {"falloff", "constant"}, {"channels", {{"label", 3}}}},
        {{"tool", "paint"}, {"points", points}, {"radius", 2 * radius}, {"channels", {{"diffuse", {1, 0.2, 0.1}}}}}}}};
  std::ofstream(path) << script.dump();
}

//! `meshpaint paint` of the stroke script on the fitted project (saved as a
//! project), then `meshpaint transfer` of that back onto the scan as PLY,
//! each in a child process.
std::pair<FitRun, FitRun> paint_and_transfer(const std::string& program, const fs::path& scan,
                                             const fs::path& strokes, const std::vector<std::string>& passed,
                                             const fs::path& folder)
{
  const fs::path painted = folder / "painted.meshpaint";
  std::vector<std::string> paint = {program, "paint", (folder / "scan.meshpaint").string(), "--strokes",
                                    strokes.string(), "--save", painted.string(), "--quiet",
                                    "-o", (folder / "painted").string()};
  paint.insert(paint.end(), passed.begin(), passed.end());
  const FitRun painting = run_measured(paint, folder / "paint.txt", folder / "paint.err");
  FitRun transfer;
  if (painting.failure.empty()) {
    std::vector<std::string> argv = {program, "transfer", painted.string(), "--to", scan.string(),
                                     "-o", (folder / "transferred.ply").string(), "--quiet"};
    argv.insert(argv.end(), passed.begin(), passed.end());
    transfer = run_measured(argv, folder / "transfer.txt", folder / "transfer.err");
  }
  fs::remove_all(folder / "painted");
  fs::remove(folder / "transferred.ply");
  return {painting, transfer};
}

//! A row's error cells: RMS and max % both ways, and the folded patches.
std::vector<std::string> error_cells(const nlohmann::json& r)
{
  return {format_fixed(r["scan_to_fit"]["rms_percent"].get<double>(), 4),
          format_fixed(r["scan_to_fit"]["max_percent"].get<double>(), 4),
          format_fixed(r["fit_to_scan"]["rms_percent"].get<double>(), 4),
          format_fixed(r["fit_to_scan"]["max_percent"].get<double>(), 4), std::to_string(r["folded_patches"].get<int>())};
}

//! The run as one flat JSON object.
nlohmann::json run_json(const FitRun& run)
{
  const nlohmann::json& r = run.report;
  return {{"triangles", r["scan_faces"]},
          {"vertices", r["scan_vertices"]},
          {"wall_s", run.wall_s},
          {"decimate_s", r["decimate_s"]},
          {"fit_s", r["fit_s"]},
          {"peak_mib", run.peak_mib},
          {"budget", r["budget"]},
          {"base_faces", r["base_faces"]},
          {"decimation_stages", r["decimation_stages"]},
          {"decimation_stage_faces", r["decimation_stage_faces"]},
          {"scan_to_fit_rms_percent", r["scan_to_fit"]["rms_percent"]},
          {"scan_to_fit_max_percent", r["scan_to_fit"]["max_percent"]},
          {"fit_to_scan_rms_percent", r["fit_to_scan"]["rms_percent"]},
          {"fit_to_scan_max_percent", r["fit_to_scan"]["max_percent"]},
          {"folds", r["folded_patches"]}};
}

} // namespace

int bench_fit(const Args& args)
{
  args.expect_positionals(1, 1, "fit [--level L] [--max-triangles N] [--json] [--quiet]");
  const int level = args.integer("--level", 3, 1, kMaxLevel);
  const std::size_t max_triangles = std::size_t(args.integer("--max-triangles", kLargest, 1000, 200000000));
  const bool json = args.flag("--json");
  const std::string source = scans_dir() + "/femur.off";
  TriMesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, source))
    throw IOError("cannot read " + source + " (scripts/fetch-scans.sh puts the scans there)");
  const auto box = [&] {
    TriMesh::Point lo = mesh.point(*mesh.vertices_begin()), hi = lo;
    for (auto v : mesh.vertices()) {
      lo.minimize(mesh.point(v));
      hi.maximize(mesh.point(v));
    }
    return (hi - lo).norm();
  };
  const double sigma = kNoise * box();

  const fs::path folder = fs::temp_directory_path() / ("meshpaint-bench-fit-" + std::to_string(getpid()));
  fs::create_directories(folder);
  const std::string program = program_folder() + "meshpaint";
  std::vector<std::string> passed;
  for (const char* option : {"--device", "--storage"})
    if (args.has(option))
      passed.insert(passed.end(), {option, args.value(option)});

  // Every scan as it is, at the default budget.
  std::vector<fs::path> scans;
  for (const auto& entry : fs::directory_iterator(scans_dir()))
    if (entry.is_regular_file() || entry.is_symlink())
      scans.push_back(entry.path());
  std::sort(scans.begin(), scans.end());
  ProgressBar bar("meshpaint bench", args.flag("--quiet"));
  Table scan_table({"scan", "triangles", "budget", "faces after each stage", "wall s", "decimate s", "fit s", "peak MiB",
                    "scan->fit RMS %", "max %", "fit->scan RMS %", "max %", "folds"});
  nlohmann::json scan_rows = nlohmann::json::array();
  std::optional<ProgressTask> task;
  task.emplace(&bar, "fitting " + counted(scans.size(), "scan", "scans") + " at level " + std::to_string(level),
               scans.size());
  for (std::size_t k = 0; k < scans.size(); ++k) {
    const fs::path& scan = scans[k];
    task->step(k);
    const FitRun run = fit_scan(program, scan, level, passed, folder);
    if (!run.failure.empty()) {
      bar.print("meshpaint bench: the fit of " + scan.string() + " failed (" + run.failure + ")");
      continue;
    }
    const nlohmann::json& r = run.report;
    std::string stages;
    for (const auto& faces : r["decimation_stage_faces"])
      stages += (stages.empty() ? "" : " > ") + grouped(faces.get<std::size_t>());
    std::vector<std::string> cells = {scan.stem().string(), grouped(r["scan_faces"].get<std::size_t>()),
                                      grouped(r["budget"].get<std::size_t>()), stages, format_fixed(run.wall_s, 1),
                                      format_fixed(r["decimate_s"].get<double>(), 1), format_fixed(r["fit_s"].get<double>(), 1),
                                      format_fixed(run.peak_mib, 0)};
    for (const std::string& c : error_cells(r))
      cells.push_back(c);
    scan_table.add(cells);
    nlohmann::json j = run_json(run);
    j["name"] = scan.stem().string();
    scan_rows.push_back(j);
  }
  task->step(scans.size());

  // The decimation step alone against its peers, on the scan as fit imports
  // it and at fit's default budget.
  Table peer_table({"scan", "budget", "method", "faces", "median s", "scan->decimated RMS %", "max %"});
  nlohmann::json peer_rows = nlohmann::json::array();
  task.emplace(&bar, "decimating " + counted(scans.size(), "scan", "scans") + " by each method", scans.size());
  for (std::size_t k = 0; k < scans.size(); ++k) {
    const fs::path& scan = scans[k];
    task->step(k);
    const BaseMesh mesh = is_polydata_path(scan.string()) ? load_polydata_mesh(scan.string()) : load_mesh(scan.string());
    const std::size_t budget = default_base_faces(mesh.face_count());
    const double diagonal = mesh.diagonal();
    for (const DecimationPeer& peer : decimation_peers(mesh, budget, kDecimationRepeats)) {
      const double rms = 100 * peer.scan_to_mesh.rms / diagonal, max = 100 * peer.scan_to_mesh.max / diagonal;
      peer_table.add({scan.stem().string(), grouped(budget), peer.method, grouped(peer.faces),
                      format_fixed(peer.seconds, 3), format_fixed(rms, 4), format_fixed(max, 4)});
      peer_rows.push_back({{"name", scan.stem().string()},
                           {"budget", budget},
                           {"method", peer.method},
                           {"faces", peer.faces},
                           {"time_s", peer.seconds},
                           {"scan_to_decimated_rms_percent", rms},
                           {"scan_to_decimated_max_percent", max}});
    }
  }
  task->step(scans.size());

  Table table({"triangles", "vertices", "subdivisions", "wall s", "decimate s", "fit s", "peak MiB", "base faces",
               "scan->fit RMS %", "max %", "fit->scan RMS %", "max %", "folds"});
  nlohmann::json rows = nlohmann::json::array();
  Table series_peers({"triangles", "budget", "method", "faces", "s", "scan->decimated RMS %", "max %"});
  nlohmann::json series_peer_rows = nlohmann::json::array();
  // The series: Loop steps (4 times the triangles each), then the scan of
  // 10^7, which no number of Loop steps makes: two Loop steps and four of
  // Kobbelt's sqrt(3) (3 times each).
  struct Refinement
  {
    int loop = 0, sqrt3 = 0;
  };
  std::vector<Refinement> series;
  const std::size_t femur_faces = mesh.n_faces();
  for (int k = 1; femur_faces << (2 * k) <= max_triangles; ++k)
    if (femur_faces << (2 * k) >= kSmallest)
      series.push_back({k, 0});
  if (femur_faces * 16 * 81 <= max_triangles)
    series.push_back({2, 4});
  const TriMesh femur = mesh;
  const fs::path strokes = folder / "strokes.json";
  write_femur_strokes(femur, strokes);
  Table painting({"triangles", "scan vertices", "paint s", "paint peak MiB", "transfer s", "transfer peak MiB"});
  task.emplace(&bar, "fitting the femur at " + counted(series.size(), "size", "sizes"), series.size());
  for (std::size_t sized = 0; sized < series.size(); ++sized) {
    const Refinement step = series[sized];
    mesh = femur;
    OpenMesh::Subdivider::Uniform::LoopT<TriMesh> loop;
    loop.attach(mesh);
    loop(std::size_t(step.loop));
    loop.detach();
    OpenMesh::Subdivider::Uniform::Sqrt3T<TriMesh> sqrt3;
    sqrt3.attach(mesh);
    sqrt3(std::size_t(step.sqrt3));
    sqrt3.detach();
    const fs::path scan = folder / "scan.ply";
    write_noisy(mesh, sigma, unsigned(step.loop + 10 * step.sqrt3), scan);
    task->step(sized);
    FitRun run = fit_scan(program, scan, level, passed, folder);
    run.triangles = mesh.n_faces();
    run.vertices = mesh.n_vertices();
    if (!run.failure.empty()) {
      bar.print("meshpaint bench: the fit of " + grouped(run.triangles) + " triangles failed (" + run.failure +
                "); larger scans are not tried");
      break;
    }
    const nlohmann::json& r = run.report;
    if (run.triangles <= kSeriesPeerTriangles) {
      // The decimation's peers on the same scan at the budget the fit used.
      const BaseMesh imported = load_mesh(scan.string());
      const std::size_t budget = r["budget"].get<std::size_t>();
      for (const DecimationPeer& peer : decimation_peers(imported, budget, 1)) {
        const double d = imported.diagonal();
        series_peers.add({grouped(run.triangles), grouped(budget), peer.method, grouped(peer.faces),
                          format_fixed(peer.seconds, 2), format_fixed(100 * peer.scan_to_mesh.rms / d, 4),
                          format_fixed(100 * peer.scan_to_mesh.max / d, 4)});
        series_peer_rows.push_back({{"triangles", run.triangles},
                                    {"budget", budget},
                                    {"method", peer.method},
                                    {"faces", peer.faces},
                                    {"time_s", peer.seconds},
                                    {"scan_to_decimated_rms_percent", 100 * peer.scan_to_mesh.rms / d},
                                    {"scan_to_decimated_max_percent", 100 * peer.scan_to_mesh.max / d}});
      }
    }
    // Each fit can take minutes: its numbers as soon as it ends.
    bar.note(grouped(run.triangles) + " triangles: " + format_fixed(run.wall_s, 1) + " s, peak " +
             format_fixed(run.peak_mib, 0) + " MiB, scan->fit RMS " +
             format_fixed(r["scan_to_fit"]["rms_percent"].get<double>(), 4) + "%, max " +
             format_fixed(r["scan_to_fit"]["max_percent"].get<double>(), 4) + "%");
    const std::string steps =
      "Loop " + std::to_string(step.loop) + (step.sqrt3 > 0 ? ", sqrt3 " + std::to_string(step.sqrt3) : "");
    std::vector<std::string> cells = {grouped(run.triangles), grouped(run.vertices), steps,
                                      format_fixed(run.wall_s, 1), format_fixed(r["decimate_s"].get<double>(), 1),
                                      format_fixed(r["fit_s"].get<double>(), 1), format_fixed(run.peak_mib, 0),
                                      grouped(r["base_faces"].get<std::size_t>()) + " (" +
                                        grouped(r["budget"].get<std::size_t>()) + ")"};
    const std::vector<std::string> errors = error_cells(r);
    cells.insert(cells.end(), errors.begin(), errors.end());
    table.add(cells);
    nlohmann::json row = run_json(run);
    row["loop_steps"] = step.loop;
    row["sqrt3_steps"] = step.sqrt3;
    const auto [paint, transfer] = paint_and_transfer(program, scan, strokes, passed, folder);
    if (!paint.failure.empty() || !transfer.failure.empty())
      bar.print("meshpaint bench: painting or transferring the fit of " + grouped(run.triangles) + " triangles failed (" +
                (paint.failure.empty() ? transfer.failure : paint.failure) + ")");
    else {
      painting.add({grouped(run.triangles), grouped(run.vertices), format_fixed(paint.wall_s, 1),
                    format_fixed(paint.peak_mib, 0), format_fixed(transfer.wall_s, 1),
                    format_fixed(transfer.peak_mib, 0)});
      row["paint_wall_s"] = paint.wall_s;
      row["paint_peak_mib"] = paint.peak_mib;
      row["transfer_wall_s"] = transfer.wall_s;
      row["transfer_peak_mib"] = transfer.peak_mib;
    }
    rows.push_back(row);
    fs::remove(scan);
  }
  task->step(series.size());
  task.reset();
  fs::remove_all(folder);
  if (json) {
    const nlohmann::json out = {{"scan", "femur"}, {"level", level}, {"noise", kNoise}, {"fits", rows},
                                {"scans", scan_rows}, {"decimation", peer_rows},
                                {"series_decimation", series_peer_rows}};
    std::cout << out.dump() << "\n";
    return 0;
  }
  std::cout << "meshpaint fit on every scan in " << scans_dir() << ", default budget, level " << level << "\n";
  scan_table.print(std::cout);
  std::cout << "\n";
  std::cout << "decimation alone at fit's default budget, median of " << kDecimationRepeats << " runs\n";
  peer_table.print(std::cout);
  std::cout << "\n";
  std::cout << "meshpaint fit on femur refined by Loop and sqrt(3) subdivision, noise " << kNoise * 100
            << "% of the diagonal per coordinate, level " << level << "\n";
  table.print(std::cout);
  std::cout << "\n";
  std::cout << "the stroke script (a label and a paint stroke along the femur) painted on each fitted project, "
               "and the result transferred back onto the scan's vertices as PLY\n";
  painting.print(std::cout);
  std::cout << "\n";
  std::cout << "decimation of those scans up to " << grouped(kSeriesPeerTriangles)
            << " triangles at the budget fit used, one run each\n";
  series_peers.print(std::cout);
  return 0;
}

} // namespace meshpaint::cli
