// meshpaint bench subdivide: the atlas kernels against OpenSubdiv, measured
// in one run on the same mesh and level, with the results compared.

#include "benchmarks.h"
#include "device_bandwidth.h"
#include "host_memory.h"
#include "kernel_traffic.h"
#include "progress_bar.h"
#include "table.h"

#include "atlas/atlas.h"
#include "atlas/weld.h"
#include "cl/kernel_clock.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "mesh/far_refiner.h"
#include "reference/opensubdiv_reference.h"

#include <cmath>    // for std::sqrt
#include <iostream> // for std::cout
#include <map>      // for std::map
#include <optional> // for std::optional

namespace meshpaint::cli {
namespace {

template <typename F>
std::vector<double> time_repeats(int repeats, F&& run)
{
  run(); // warm-up: kernel compilation, page faults, caches
  std::vector<double> ms;
  for (int r = 0; r < repeats; ++r) {
    Timer t;
    run();
    ms.push_back(t.ms());
  }
  return ms;
}

double min_of(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

//! Device time per kernel family of `runs` subdivisions from level `from`
//! to `to`, after one untimed, with the bytes each family moves.
std::vector<FamilyRate> family_times(Runtime& runtime, Atlas& atlas, int from, int to, int runs)
{
  atlas.subdivide(from, to);
  atlas.finish();
  KernelClock clock(runtime);
  for (int r = 0; r < runs; ++r)
    atlas.subdivide(from, to);
  return family_rates(subdivide_traffic(atlas.topology(), from, to, atlas.evaluator()),
                      clock.take(), runs);
}

} // namespace

int bench_subdivide(const Args& args)
{
  args.expect_positionals(2, 2, "subdivide MESH --level L [--json] [--repeats N]");
  const std::string path = args.positionals()[1];
  const int level = args.integer("--level", 3, 2, kMaxLevel);
  const int repeats = args.integer("--repeats", 15, 1, 1000);
  const bool json = args.flag("--json");
  const BaseMesh mesh = load_reported(path);
  auto runtime = open_device(args);
  const AtlasStorage storage =
    args.has("--storage") ? parse_storage(args.value("--storage")) : default_storage(runtime->info());

  ProgressBar bar("meshpaint bench", args.flag("--quiet"));
  std::optional<ProgressTask> task;
  task.emplace(&bar, "subdivide to level " + std::to_string(level) + ", " + std::to_string(repeats) + " runs each", 3);
  Timer t;
  Atlas atlas(runtime, mesh, level, storage);
  const double atlas_ms = t.ms();
  const std::vector<double> engine = time_repeats(repeats, [&] {
    atlas.subdivide(1, level);
    atlas.finish();
  });

  // OpenSubdiv gets the same spatially ordered mesh the atlas works on.
  const BaseMesh& base = atlas.base_mesh();
  StencilPeer peer(base, level);
  task->step(1);
  const std::vector<double> osd = time_repeats(repeats, [&] { peer.evaluate(); });
  task->step(2);

  // Far::PrimvarRefiner, level by level: OpenSubdiv's other CPU path.
  auto refiner = make_refiner(base);
  refine_uniform(*refiner, level, false);
  const std::vector<double> primvar =
    time_repeats(std::max(1, repeats / 3), [&] { interpolate_levels(*refiner, base.points); });
  task->step(3);
  task.reset();

  // Both must have computed the same surface, or the timings mean nothing.
  const WeldedSurface ours = level_surface(atlas, level, false);
  const std::vector<int> order = opensubdiv_vertex_order(base, atlas.topology(), level);
  const std::vector<Vec3> theirs = peer.result();
  double worst = 0;
  for (std::size_t v = 0; v < ours.points.size(); ++v) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k)
      d2 += std::pow(double(ours.points[v][k]) - theirs[order[v]][k], 2);
    worst = std::max(worst, std::sqrt(d2));
  }
  const double deviation = worst / mesh.diagonal();
  if (!(deviation <= 1e-5))
    throw std::runtime_error("meshpaint and OpenSubdiv disagree by " + std::to_string(deviation) +
                             " of the diagonal");

  const std::size_t verts = ours.points.size();
  std::size_t engine_bytes = 0, texels = 0;
  for (int l = 1; l < level; ++l) {
    const std::size_t a = std::size_t(atlas.topology().patch_count) * atlas.layout(l).tile * atlas.layout(l).tile;
    const std::size_t b = std::size_t(atlas.topology().patch_count) * atlas.layout(l + 1).tile * atlas.layout(l + 1).tile;
    engine_bytes += 16 * (a + b); // every texel read once and written once per step
    texels = b;
  }
  const double e_ms = median(engine), o_ms = median(osd), p_ms = median(primvar);
  const auto mverts = [&](double ms) { return double(verts) / (ms * 1e3); };
  const auto gbps = [](std::size_t bytes, double ms) { return double(bytes) / (ms * 1e6); };

  // Where the device time goes, per family and per step, against what the
  // device can copy: separate runs with profiling events, after the timed ones.
  const DeviceBandwidth copy = probe_device_bandwidth(*runtime);
  const std::vector<FamilyRate> families = family_times(*runtime, atlas, 1, level, repeats);
  std::vector<FamilyRate> steps;
  for (int l = 1; l < level; ++l) {
    FamilyRate all = family_times(*runtime, atlas, l, l + 1, repeats).back();
    all.family = "level " + std::to_string(l) + "->" + std::to_string(l + 1);
    steps.push_back(all);
  }
  std::string json_steps;
  for (std::size_t k = 0; k < steps.size(); ++k)
    json_steps += std::string(k ? "," : "") + "{\"from\":" + std::to_string(k + 1) + ",\"to\":" +
                  std::to_string(k + 2) + ",\"ms\":" + std::to_string(steps[k].ms) + ",\"gb_per_s\":" +
                  std::to_string(steps[k].gbps) + "}";

  const HostMemory host = probe_host_memory();
  if (json) {
    std::cout << "{\"mesh\":" << json_string(path) << ",\"level\":" << level << ",\"vertices\":" << verts
              << ",\"texels\":" << texels << ",\"device\":" << json_string(runtime->info().name) << ",\"storage\":\""
              << storage_name(storage) << "\",\"repeats\":" << repeats << ",\"engine_ms\":" << e_ms
              << ",\"engine_min_ms\":" << min_of(engine) << ",\"opensubdiv_ms\":" << o_ms
              << ",\"opensubdiv_min_ms\":" << min_of(osd) << ",\"primvar_ms\":" << p_ms
              << ",\"ratio\":" << o_ms / e_ms << ",\"engine_mverts_per_s\":" << mverts(e_ms)
              << ",\"opensubdiv_mverts_per_s\":" << mverts(o_ms)
              << ",\"engine_gb_per_s\":" << gbps(engine_bytes, e_ms)
              << ",\"opensubdiv_gb_per_s\":" << gbps(peer.bytes_moved(), o_ms)
              << ",\"atlas_setup_ms\":" << atlas_ms << ",\"stencil_build_ms\":" << peer.build_ms()
              << ",\"max_deviation\":" << deviation << ",\"host_memory_ns\":" << host.json()
              << ",\"device_copy_gb_per_s\":" << copy.json() << ",\"kernel_families\":" << family_json(families)
              << ",\"level_steps\":[" << json_steps << "]}\n";
    return 0;
  }
  std::ostream& os = std::cout;
  os << "meshpaint bench subdivide: " << path << ", level " << level << "\n";
  os << "  base mesh " << grouped(mesh.vertex_count()) << " vertices, " << grouped(mesh.face_count())
     << " faces; level " << level << ": " << grouped(verts) << " vertices (" << grouped(texels)
     << " atlas texels)\n";
  os << "  device " << runtime->info().summary() << ", " << storage_name(storage) << " storage; median of "
     << repeats << " runs after a warm-up\n"
     << "  " << host.text() << "\n\n";
  Table table({"method", "median ms", "min ms", "Mverts/s", "GB/s"});
  table.add({"meshpaint kernels (levels 1->" + std::to_string(level) + ")", format_fixed(e_ms, 2),
             format_fixed(min_of(engine), 2), format_fixed(mverts(e_ms), 1),
             format_fixed(gbps(engine_bytes, e_ms), 1)});
  table.add({"OpenSubdiv Far::StencilTable + Osd::CpuEvaluator (0->" + std::to_string(level) + ")",
             format_fixed(o_ms, 2), format_fixed(min_of(osd), 2), format_fixed(mverts(o_ms), 1),
             format_fixed(gbps(peer.bytes_moved(), o_ms), 1)});
  table.add({"OpenSubdiv Far::PrimvarRefiner (0->" + std::to_string(level) + ")", format_fixed(p_ms, 2),
             format_fixed(min_of(primvar), 2), format_fixed(mverts(p_ms), 1), "-"});
  table.print(os);
  os << "\n  speed-up over Osd::CpuEvaluator: " << format_fixed(o_ms / e_ms, 2) << "x\n";
  os << "  one-off set-up (not timed above): atlas " << format_fixed(atlas_ms, 1)
     << " ms (first step, tables, upload, kernel build); stencil table " << format_fixed(peer.build_ms(), 1)
     << " ms\n";
  os << "  results agree: max distance " << deviation << " of the bounding-box diagonal\n\n";
  os << "device time per kernel family (profiling events, mean of " << repeats
     << " further runs) and bytes read + written per time\n  " << copy.text() << "\n\n";
  Table rates({"subdivision", "kernels", "device ms", "GB/s", "of copy"});
  add_family_rows(rates, "levels 1->" + std::to_string(level), families, copy.best());
  add_family_rows(rates, "per step", steps, copy.best());
  rates.print(os);
  return 0;
}

} // namespace meshpaint::cli
