#include "commands.h"
#include "table.h"

#include "atlas/atlas.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/host_memory.h"
#include "mesh/decimate.h"
#include "mesh/mesh_stats.h"
#include "paint/paint_memory.h"
#include "project/fit_memory.h"
#include "project/project_surface.h"

#include <cstdio>   // for std::snprintf
#include <iostream> // for std::cout
#include <optional> // for std::optional

namespace meshpaint::cli {
namespace {

std::string histogram(const std::map<int, std::size_t>& h, const std::map<int, std::string>& names)
{
  std::string out;
  for (const auto& [k, count] : h) {
    const auto it = names.find(k);
    const std::string one = it != names.end() ? it->second : std::to_string(k) + "-gon";
    out += (out.empty() ? "" : ", ") + counted(count, one, one + "s", true);
  }
  return out;
}

std::string hex32(std::uint32_t v)
{
  char text[9];
  std::snprintf(text, sizeof text, "%08x", v);
  return text;
}

} // namespace

int info_command(const Argv& argv)
{
  Args args("info", argv, {"--no-weld"}, {"--device", "--storage", "--import-array", "--level", "--base-faces"});
  args.expect_positionals(1, 1, "MESH|PROJECT");
  // What `meshpaint fit` of this mesh would need, at fit's options.
  const int fit_level = args.integer("--level", 3, 1, kMaxLevel);
  const int fit_base_faces = args.integer("--base-faces", 0, 4, 10000000);
  const std::string path = args.positionals()[0];
  const MeshOrProject input = open_mesh_or_project(path, import_options(args));
  const BaseMesh& mesh = input.mesh();
  const MeshStats s = compute_stats(mesh);
  std::ostream& os = std::cout;

  os << "mesh         " << path << "\n";
  os << "counts       " << counted(s.vertices, "vertex", "vertices", true) << ", "
     << counted(s.edges, "edge", "edges", true) << ", " << counted(s.faces, "face", "faces", true) << " ("
     << histogram(s.faces_by_size, {{3, "triangle"}, {4, "quad"}}) << ")\n";
  os << "topology     " << counted(s.components, "component", "components") << ", genus " << s.genus
     << ", Euler characteristic " << s.euler_characteristic << "\n";
  os << "boundaries   " << counted(s.boundary_loops, "loop", "loops") << ", "
     << counted(s.boundary_edges, "edge", "edges", true) << "\n";
  std::size_t vsum = 0;
  for (const auto& [v, count] : s.valences)
    vsum += std::size_t(v) * count;
  os << "valences     min " << s.valences.begin()->first << ", max " << s.valences.rbegin()->first
     << ", mean " << format_fixed(double(vsum) / double(s.vertices), 2) << "\n";
  os << "bounds       (" << s.bbox_min[0] << ", " << s.bbox_min[1] << ", " << s.bbox_min[2] << ") - ("
     << s.bbox_max[0] << ", " << s.bbox_max[1] << ", " << s.bbox_max[2] << "), diagonal "
     << mesh.diagonal() << "\n";
  auto repairs = mesh.report.lines();
  for (const std::string& step : mesh.report.step_lines())
    repairs.push_back(step);
  os << "import       " << (repairs.empty() ? "no repairs" : repairs.front()) << "\n";
  for (std::size_t r = 1; r < repairs.size(); ++r)
    os << "             " << repairs[r] << "\n";

  if (input.project) {
    const Project& p = *input.project;
    std::string names;
    for (const LabelClass& c : p.labels)
      names += (names.empty() ? " (" : ", ") + std::to_string(c.id) + " " + c.name;
    os << "project      level " << p.level << ", " << counted(p.positions.size(), "texel", "texels", true) << ", "
       << counted(p.labels.size(), "label", "labels") << (names.empty() ? "" : names + ")") << "\n";
    os << "history      " << counted(stroke_history(p.history).strokes.size(), "stroke", "strokes") << "\n";
    os << "scan         "
       << (p.scan.path.empty() ? std::string("none")
                               : p.scan.path + ", " + grouped(p.scan.bytes) + " bytes, CRC-32 " + hex32(p.scan.crc32))
       << "\n";
  }
  // A scan of millions of faces as its own base mesh: its atlas tables
  // alone can take more memory than a fit of it, so they are planned first.
  const std::size_t available = available_host_memory();
  const std::size_t topology_bytes = atlas_topology_bytes(mesh);
  const bool tabled = available == 0 || topology_bytes <= available / 2;
  std::optional<AtlasTopology> topo;
  if (tabled) {
    topo = atlas_topology_of(mesh);
    os << "atlas        " << grouped(topo->patch_count) << " patches (quads after the first Catmull-Clark step), "
       << grouped(topo->rings.size()) << " corner rings, " << grouped(topo->edges.size()) << " patch edges\n";
  } else {
    os << "atlas        " << grouped(mesh.face_vertices.size())
       << " patches (quads after the first Catmull-Clark step), not tabled: their tables would take about "
       << format_bytes(topology_bytes) << ", over half of the " << format_bytes(available)
       << " available (fit makes a base mesh to paint: see below)\n";
  }

  std::shared_ptr<Runtime> runtime;
  std::string no_device;
  try {
    runtime = open_device(args);
  } catch (const DeviceError& e) {
    no_device = e.what();
  }
  const AtlasStorage storage = args.has("--storage") ? parse_storage(args.value("--storage"))
                               : runtime ? default_storage(runtime->info()) : AtlasStorage::Buffer;
  os << "device       " << (runtime ? runtime->info().summary() + ", " + storage_name(storage) + " storage"
                                    : "none: " + no_device) << "\n";

  if (topo) {
    os << "\n";
    Table table({"level", "patch", "atlas texels", "vertices", "faces", "layer", "atlas 1..L", "painting",
                 "coarse edits", "fits"});
    // Without a device, the plans are a CPU's (buffer storage, a work item per patch).
    const DeviceInfo device = runtime ? runtime->info() : DeviceInfo();
    const auto within = [&](std::size_t bytes) {
      return format_bytes(bytes) + (runtime && bytes > device.global_memory ? " (over)" : "");
    };
    const int top = runtime ? std::min(kMaxLevel, largest_fitting_level(*topo, runtime->info(), storage) + 1) : 6;
    for (int l = 1; l <= std::max(top, 1); ++l) {
      const MemoryPlan plan = plan_memory(*topo, l, storage);
      const LevelLayout& lay = plan.finest;
      table.add({std::to_string(l), std::to_string(lay.tile) + "x" + std::to_string(lay.tile),
                 std::to_string(lay.width) + "x" + std::to_string(lay.height), grouped(topo->unique_vertices(l)),
                 grouped(std::size_t(topo->patch_count) * lay.n * lay.n), format_bytes(layer_bytes(lay, storage)),
                 format_bytes(plan.total), within(painting_bytes(*topo, l, storage)),
                 l > 1 ? within(coarse_edits_bytes(*topo, l, storage, device)) : std::string("-"),
                 runtime ? (fit_problem(*topo, l, runtime->info(), storage).empty() ? "yes" : "no") : "?"});
    }
    table.print(os);
  }

  const FitMemory fit = plan_fit_memory(
      mesh.triangle_count(), fit_base_faces > 0 ? std::size_t(fit_base_faces) : default_base_faces(mesh.face_count()),
      fit_level);
  os << "\nfit          level " << fit_level << ", base mesh " << counted(fit.base_faces, "face", "faces", true)
     << ": about " << grouped(fit.points) << " points, " << format_bytes(fit.bytes) << " of host memory at the peak"
     << (available == 0 ? std::string(" (available memory unknown)")
         : ", " + format_bytes(available) + " available: " + (fit.bytes <= available ? "fits" : "does not fit"))
     << "\n";
  return 0;
}

} // namespace meshpaint::cli
