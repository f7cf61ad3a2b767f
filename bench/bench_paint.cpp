// meshpaint bench paint: the paper's Table 1 on this machine (brush step
// time by mesh size and brush size), and full-surface smoothing against VTK
// and OpenMesh on the same surface, all in one run.

#include "benchmarks.h"
#include "device_bandwidth.h"
#include "host_memory.h"
#include "kernel_traffic.h"
#include "progress_bar.h"
#include "table.h"

#include "SurfaceConversion.h"

#include "atlas/weld.h"
#include "cl/kernel_clock.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/timer.h"
#include "mesh/openmesh_types.h"
#include "paint/paint_surface.h"

#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh> // for JacobiLaplaceSmootherT

#include <vtkSmoothPolyDataFilter.h> // for vtkSmoothPolyDataFilter

#include <algorithm> // for std::nth_element
#include <array>     // for std::array
#include <optional>  // for std::optional
#include <cmath>     // for std::sqrt
#include <iostream>  // for std::cout
#include <iterator>  // for std::size

namespace meshpaint::cli {
namespace {

struct Row
{
  std::string mesh;
  int level;
  double paper_ms[3]; // GeForce 7800, brush + rendering (Ritschel et al., Table 1)
};

// Meshes near the paper's 100k, 600k and 2.3M faces, at the painting level.
const Row kRows[] = {{"femur.off", 2, {30, 30, 30}},
                     {"armadillo.off", 2, {60, 80, 100}},
                     {"armadillo.off", 3, {120, 220, 390}}};
const double kCoverage[3] = {0.01, 0.10, 0.50};

//! Radius around `centre` whose ball holds `fraction` of the texels: texels
//! sample the surface about evenly, so this is about that share of the area.
float radius_for(const std::vector<Float4>& texels, const Vec3& centre, double fraction)
{
  std::vector<float> d(texels.size());
  for (std::size_t t = 0; t < texels.size(); ++t)
    d[t] = std::sqrt((texels[t][0] - centre[0]) * (texels[t][0] - centre[0]) +
                     (texels[t][1] - centre[1]) * (texels[t][1] - centre[1]) +
                     (texels[t][2] - centre[2]) * (texels[t][2] - centre[2]));
  const std::size_t k = std::min(d.size() - 1, std::size_t(fraction * double(d.size())));
  std::nth_element(d.begin(), d.begin() + long(k), d.end());
  return d[k];
}

//! Median step time of a brush at each coverage: a warm-up, then `steps`.
std::array<double, 3> step_times(PaintSurface& surface, Stroke s, const std::vector<Float4>& texels, int steps)
{
  std::array<double, 3> ms{};
  for (int c = 0; c < 3; ++c) {
    s.brush.radius = radius_for(texels, s.points.front(), kCoverage[c]);
    surface.apply(s); // warm-up (and, at a coarse edit level, the details' encoding)
    std::vector<double> t;
    for (int k = 0; k < steps; ++k)
      t.push_back(surface.apply(s).ms);
    ms[std::size_t(c)] = median(t);
  }
  return ms;
}

//! Coarse edits keep their details from stroke to stroke and encode them
//! again after an edit at the finest level. Medians of: a further dab (from
//! strokes of 1 and of 9 dabs at about one place: what a drag costs per
//! dab), a whole stroke of one dab with the details kept, and the encoding
//! at the first coarse stroke after a finest-level stroke (which the
//! stroke's report times alone).
std::array<std::array<double, 3>, 3> coarse_step_times(PaintSurface& surface, Stroke s,
                                                        const std::vector<Float4>& texels, int steps)
{
  std::array<std::array<double, 3>, 3> out{};
  const Vec3 at = s.points.front();
  for (int c = 0; c < 3; ++c) {
    s.brush.radius = radius_for(texels, at, kCoverage[c]);
    s.brush.spacing = 0.01f;
    Stroke nine = s; // 8 more dabs 0.01 radius apart
    nine.points.push_back({at[0] + 0.08f * s.brush.radius, at[1], at[2]});
    Stroke fine = s; // moves nothing, but is a finest-level edit
    fine.move().edit_level = 0;
    fine.move().amount = 0.f;
    surface.apply(s); // warm-up
    std::vector<double> one, more, encoding;
    for (int k = 0; k < steps; ++k) {
      one.push_back(surface.apply(s).ms);
      more.push_back(surface.apply(nine).ms);
      surface.apply(fine);
      encoding.push_back(surface.apply(s).encode_ms);
    }
    out[0][std::size_t(c)] = std::max(0.0, (median(more) - median(one)) / 8.0);
    out[1][std::size_t(c)] = median(one);
    out[2][std::size_t(c)] = median(encoding);
  }
  return out;
}

//! The phases of a step (StepPhases, in its field order) and their sum.
const char* const kPhaseNames[] = {"place", "record", "weights", "transform", "rebuild", "lists", "limit"};
constexpr double StepPhases::*kPhaseFields[] = {&StepPhases::place,     &StepPhases::record, &StepPhases::weights,
                                                &StepPhases::transform, &StepPhases::rebuild, &StepPhases::lists,
                                                &StepPhases::limit};

//! Median time of each phase of a step at the largest coverage, with a wait
//! for the device after each phase; the last entry is the whole step's.
std::vector<double> phase_times(PaintSurface& surface, Stroke s, const std::vector<Float4>& texels, int steps)
{
  s.brush.radius = radius_for(texels, s.points.front(), kCoverage[2]);
  surface.time_phases(true);
  surface.apply(s); // warm-up
  std::vector<std::vector<double>> t(std::size(kPhaseFields) + 1);
  for (int k = 0; k < steps; ++k) {
    const StrokeReport r = surface.apply(s);
    for (std::size_t f = 0; f < std::size(kPhaseFields); ++f)
      t[f].push_back(r.phases.*kPhaseFields[f]);
    t.back().push_back(r.ms);
  }
  surface.time_phases(false);
  std::vector<double> out;
  for (std::vector<double>& v : t)
    out.push_back(median(v));
  return out;
}

//! Device time per kernel family of the limit over the whole surface (the
//! update of a step runs the same kernels on the patches it touched): `runs`
//! evaluations after one untimed, with the bytes each family moves.
std::vector<FamilyRate> limit_family_times(Runtime& runtime, Atlas& atlas, int runs)
{
  atlas.compute_limit();
  atlas.finish();
  KernelClock clock(runtime);
  for (int r = 0; r < runs; ++r)
    atlas.compute_limit();
  return family_rates(limit_traffic(atlas.topology(), atlas.max_level()), clock.take(), runs);
}

std::string json_list(const std::array<double, 3>& v)
{
  return "[" + std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]) + "]";
}

struct SmoothingResult
{
  std::size_t vertices = 0;
  double meshpaint_ms = 0, vtk_ms = 0, openmesh_ms = 0; //!< per further iteration
  double meshpaint_stroke_ms = 0;                       //!< a whole stroke of `iterations`
};

//! The cost of one further iteration: runs of `iterations` and of `more`
//! further ones, each the median of `repeats`, so that what a run pays once
//! (a stroke's culling, weights and limit update; VTK's and OpenMesh's
//! set-up) drops out for every method alike. Also returns the median run of
//! `iterations`.
template <typename Run>
double per_iteration(int iterations, int more, int repeats, Run run, double* whole = nullptr)
{
  std::vector<double> base, longer;
  for (int k = 0; k < repeats; ++k) {
    base.push_back(run(iterations));
    longer.push_back(run(iterations + more));
  }
  if (whole)
    *whole = median(base);
  return (median(longer) - median(base)) / more;
}

//! Further iterations per run: enough on a small mesh that their time stands
//! well above the noise of a run's one-off costs.
int further_iterations(std::size_t vertices) { return vertices < 250000 ? 100 : 20; }

//! Per-iteration time of Laplacian smoothing of the whole level-L surface.
SmoothingResult bench_smoothing(PaintSurface& surface, int iterations, int repeats)
{
  SmoothingResult r;
  const WeldedSurface welded = level_surface(surface.atlas(), surface.level(), false);
  r.vertices = welded.points.size();
  const double diagonal = surface.atlas().base_mesh().diagonal();

  Stroke s = make_stroke(Tool::Smooth);
  s.points = {surface.atlas().base_mesh().points.front()};
  s.brush.radius = float(4 * diagonal); // the whole surface
  s.brush.falloff = FALLOFF_CONSTANT;
  s.smooth().taubin = false;
  const int more = further_iterations(r.vertices);
  r.meshpaint_ms = per_iteration(
    iterations, more, repeats,
    [&](int n) {
      s.smooth().iterations = n;
      return surface.apply(s).ms;
    },
    &r.meshpaint_stroke_ms);

  vtkSmartPointer<vtkPolyData> poly = to_polydata(welded);
  r.vtk_ms = per_iteration(iterations, more, repeats, [&](int n) {
    auto smooth = vtkSmartPointer<vtkSmoothPolyDataFilter>::New();
    smooth->SetInputData(poly);
    smooth->SetNumberOfIterations(n);
    smooth->SetRelaxationFactor(0.5);
    smooth->FeatureEdgeSmoothingOff();
    smooth->BoundarySmoothingOn();
    smooth->SetConvergence(0.0);
    Timer t;
    smooth->Update();
    return t.ms();
  });

  PolyMesh mesh;
  for (const Vec3& p : welded.points)
    mesh.add_vertex(PolyMesh::Point(p[0], p[1], p[2]));
  for (const auto& q : welded.quads)
    mesh.add_face({PolyMesh::VertexHandle(q[0]), PolyMesh::VertexHandle(q[1]), PolyMesh::VertexHandle(q[2]),
                   PolyMesh::VertexHandle(q[3])});
  mesh.request_vertex_normals();
  mesh.request_face_normals();
  mesh.update_normals();
  r.openmesh_ms = per_iteration(iterations, more, repeats, [&](int n) {
    OpenMesh::Smoother::JacobiLaplaceSmootherT<PolyMesh> smoother(mesh);
    smoother.initialize(OpenMesh::Smoother::SmootherT<PolyMesh>::Tangential_and_Normal,
                        OpenMesh::Smoother::SmootherT<PolyMesh>::C0);
    Timer t;
    smoother.smooth(unsigned(n));
    return t.ms();
  });
  return r;
}

} // namespace

int bench_paint(const Args& args)
{
  args.expect_positionals(1, 1, "paint [--json] [--steps N] [--tool sculpt|paint] [--mesh femur|armadillo] [--phases]");
  const int steps = args.integer("--steps", 21, 1, 1000);
  const std::string tool = args.value("--tool", "sculpt");
  if (tool != "sculpt" && tool != "paint")
    throw InputError("--tool must be sculpt or paint, not '" + tool + "'");
  const bool json = args.flag("--json");
  const bool phases = args.flag("--phases");
  const std::string only = args.value("--mesh", "");
  if (!only.empty() && only != "femur" && only != "armadillo")
    throw InputError("--mesh must be femur or armadillo, not '" + only + "'");
  auto runtime = open_device(args);
  const AtlasStorage storage =
    args.has("--storage") ? parse_storage(args.value("--storage")) : default_storage(runtime->info());

  Table table({"faces", "mesh", "1% ms", "10% ms", "50% ms", "paper ms (1/10/50%)", "speed-up (1/10/50%)"});
  Table smoothing(
    {"vertices", "mesh", "meshpaint ms", "VTK ms", "OpenMesh ms", "vs VTK", "vs OpenMesh", "meshpaint stroke ms"});
  Table coarse({"faces", "mesh", "edit level", "dab 1% ms", "10% ms", "50% ms", "stroke 1% ms", "10% ms", "50% ms",
                "encoding 1% ms", "10% ms", "50% ms"});
  std::vector<std::string> phase_header{"mesh", "step"};
  for (const char* name : kPhaseNames)
    phase_header.push_back(std::string(name) + " ms");
  phase_header.push_back("whole ms");
  Table phase_table(phase_header);
  Table limit_rates({"mesh", "kernels", "device ms", "GB/s", "of copy"});
  std::string json_limit;
  const DeviceBandwidth copy = probe_device_bandwidth(*runtime);
  std::string json_rows, json_smooth, json_coarse, json_phases;
  const auto add_phases = [&](const std::string& name, const std::string& step, const std::vector<double>& ms) {
    std::vector<std::string> cells{name, step};
    std::string fields;
    for (std::size_t f = 0; f < ms.size(); ++f) {
      cells.push_back(format_fixed(ms[f], 2));
      fields += std::string(f ? "," : "") + "\"" + (f < std::size(kPhaseNames) ? kPhaseNames[f] : "whole") +
                "_ms\":" + std::to_string(ms[f]);
    }
    phase_table.add(cells);
    json_phases += std::string(json_phases.empty() ? "" : ",") + "{\"mesh\":" + json_string(name) +
                   ",\"step\":" + json_string(step) + "," + fields + "}";
  };
  ProgressBar bar("meshpaint bench", args.flag("--quiet"));
  std::size_t rows = 0, row_done = 0;
  for (const Row& row : kRows)
    rows += only.empty() || row.mesh == only + ".off";
  std::optional<ProgressTask> task;
  task.emplace(&bar, "paint on " + std::to_string(rows) + " meshes", rows);
  for (const Row& row : kRows) {
    if (!only.empty() && row.mesh != only + ".off")
      continue;
    task->step(row_done++);
    const BaseMesh mesh = load_mesh(scans_dir() + "/" + row.mesh);
    PaintSurface surface(runtime, mesh, row.level, storage);
    surface.undo_log().set_recording(false); // the paper's step has no undo
    const std::vector<Float4> texels = surface.atlas().read_limit_positions();
    const Vec3 at = surface.atlas().base_mesh().points[surface.atlas().base_mesh().vertex_count() / 2];
    const std::size_t faces = std::size_t(surface.atlas().topology().patch_count) * surface.atlas().layout(row.level).n *
                              surface.atlas().layout(row.level).n;
    Stroke s = make_stroke(tool == "paint" ? Tool::Paint : Tool::Sculpt);
    s.points = {at};
    s.brush.falloff = FALLOFF_SMOOTHSTEP;
    const float amount = float(1e-4 * mesh.diagonal());
    if (s.tool == Tool::Sculpt) {
      s.move().amount = amount;
    } else {
      s.paint().value[CHANNEL_DIFFUSE] = {0.9f, 0.2f, 0.1f, 1.f};
      s.paint().alpha[CHANNEL_DIFFUSE] = 0.5f;
    }
    const std::array<double, 3> ms = step_times(surface, s, texels, steps);
    const std::string name = row.mesh.substr(0, row.mesh.find('.')) + " L" + std::to_string(row.level);
    const std::vector<FamilyRate> limit = limit_family_times(*runtime, surface.atlas(), steps);
    add_family_rows(limit_rates, name, limit, copy.best());
    json_limit += std::string(json_limit.empty() ? "" : ",") + "{\"mesh\":" + json_string(name) +
                  ",\"families\":" + family_json(limit) + "}";
    if (phases)
      add_phases(name, tool + " 50%", phase_times(surface, s, texels, steps));
    table.add({grouped(faces), name, format_fixed(ms[0], 2), format_fixed(ms[1], 2), format_fixed(ms[2], 2),
               format_fixed(row.paper_ms[0], 0) + "/" + format_fixed(row.paper_ms[1], 0) + "/" +
                 format_fixed(row.paper_ms[2], 0),
               format_fixed(row.paper_ms[0] / ms[0], 1) + "x/" + format_fixed(row.paper_ms[1] / ms[1], 1) + "x/" +
                 format_fixed(row.paper_ms[2] / ms[2], 1) + "x"});
    json_rows += std::string(json_rows.empty() ? "" : ",") + "{\"mesh\":" + json_string(name) +
                 ",\"faces\":" + std::to_string(faces) + ",\"ms\":" + json_list(ms) + ",\"paper_ms\":[" +
                 std::to_string(row.paper_ms[0]) + "," + std::to_string(row.paper_ms[1]) + "," +
                 std::to_string(row.paper_ms[2]) + "]}";
    // Multiresolution: a sculpt step at the coarsest edit level, with the
    // finest level rebuilt and its details carried along.
    Stroke m = make_stroke(Tool::Sculpt);
    m.points = s.points;
    m.brush = s.brush;
    m.move().amount = amount;
    m.move().edit_level = 1;
    const auto mr = coarse_step_times(surface, m, texels, steps);
    if (phases)
      add_phases(name, "coarse sculpt 50%", phase_times(surface, m, texels, steps));
    coarse.add({grouped(faces), name, "1", format_fixed(mr[0][0], 2), format_fixed(mr[0][1], 2),
                format_fixed(mr[0][2], 2), format_fixed(mr[1][0], 2), format_fixed(mr[1][1], 2),
                format_fixed(mr[1][2], 2), format_fixed(mr[2][0], 1), format_fixed(mr[2][1], 1),
                format_fixed(mr[2][2], 1)});
    json_coarse += std::string(json_coarse.empty() ? "" : ",") + "{\"mesh\":" + json_string(name) +
                   ",\"faces\":" + std::to_string(faces) + ",\"edit_level\":1,\"dab_ms\":" + json_list(mr[0]) +
                   ",\"stroke_ms\":" + json_list(mr[1]) + ",\"encoding_ms\":" + json_list(mr[2]) + "}";
    if (row.level >= 2) {
      const SmoothingResult r = bench_smoothing(surface, 10, 5);
      // A difference of noisy medians can come out at or below zero: no ratio then.
      const auto ratio = [&](double peer) {
        return r.meshpaint_ms > 0 ? format_fixed(peer / r.meshpaint_ms, 1) + "x" : std::string("-");
      };
      smoothing.add({grouped(r.vertices), name, format_fixed(r.meshpaint_ms, 2), format_fixed(r.vtk_ms, 2),
                     format_fixed(r.openmesh_ms, 2), ratio(r.vtk_ms), ratio(r.openmesh_ms),
                     format_fixed(r.meshpaint_stroke_ms, 1)});
      json_smooth += std::string(json_smooth.empty() ? "" : ",") + "{\"mesh\":" + json_string(name) +
                     ",\"vertices\":" + std::to_string(r.vertices) + ",\"meshpaint_ms\":" +
                     std::to_string(r.meshpaint_ms) + ",\"vtk_ms\":" + std::to_string(r.vtk_ms) +
                     ",\"openmesh_ms\":" + std::to_string(r.openmesh_ms) +
                     ",\"meshpaint_stroke_ms\":" + std::to_string(r.meshpaint_stroke_ms) + "}";
    }
  }
  task->step(rows);
  task.reset();
  const HostMemory host = probe_host_memory();
  if (json) {
    std::cout << "{\"tool\":" << json_string(tool) << ",\"steps\":" << steps << ",\"device\":"
              << json_string(runtime->info().name) << ",\"host_memory_ns\":" << host.json() << ",\"brush\":["
              << json_rows << "],\"smoothing\":[" << json_smooth << "],\"coarse_edit\":[" << json_coarse << "]"
              << (phases ? ",\"phases\":[" + json_phases + "]" : std::string())
              << ",\"device_copy_gb_per_s\":" << copy.json() << ",\"limit_families\":[" << json_limit << "]}\n";
    return 0;
  }
  std::cout << "meshpaint bench paint: one " << tool << " brush step (culling, weights, transformation"
            << (tool == "sculpt" ? ", limit normals and bounds on the touched patches" : "")
            << "), median of " << steps << " steps after a warm-up; rendering not included\n"
            << "  device " << runtime->info().summary() << ", " << storage_name(storage) << " storage\n"
            << "  " << host.text() << "\n\n";
  table.print(std::cout);
  std::cout << "\n  the paper's figures (GeForce 7800) include rendering at 800x600\n\n"
            << "limit positions and normals over the whole surface, device time per kernel family\n"
            << "(profiling events, mean of " << steps << " runs) and bytes read + written per time\n  "
            << copy.text() << "\n\n";
  limit_rates.print(std::cout);
  std::cout << "\n"
            << "full-surface Laplacian smoothing, per iteration: runs of 10 and of 10 + N iterations (medians\n"
            << "of 5; N = " << further_iterations(0) << " below 250,000 vertices, else " << further_iterations(250000)
            << "), the difference over N, so that each method's set-up\n"
            << "drops out; the last column is a whole meshpaint stroke of 10 iterations (culling, weights,\n"
            << "smoothing, limit and bounds)\n\n";
  smoothing.print(std::cout);
  std::cout << "\nmultiresolution: one sculpt dab at edit level 1, the finest level rebuilt with its details\n"
            << "(weights on the edit level, its control points moved, subdivision to the finest level,\n"
            << "details decoded on the reach of the brush, limit normals and bounds); a whole stroke of one\n"
            << "such dab, the details kept from the stroke before; and the encoding of the details, which\n"
            << "the first coarse stroke after a finest-level edit pays; medians of " << steps << "\n\n";
  coarse.print(std::cout);
  if (phases) {
    std::cout << "\nphases of a step at 50% (--phases): medians of " << steps
              << ", each phase ended by a wait for the device (see StepPhases);\n"
              << "the coarse step's encoding is in `record` only when the details were made again\n\n";
    phase_table.print(std::cout);
  }
  return 0;
}

} // namespace meshpaint::cli
