// meshpaint stats: per-label area, centroid and bounds of a painted surface.

#include "commands.h"
#include "table.h"

#include "core/errors.h"
#include "core/format.h"
#include "project/imported_labels.h"
#include "project/label_stats.h"

#include <nlohmann/json.hpp> // for nlohmann::json

#include <iostream> // for std::cout
#include <map>      // for std::map
#include <sstream>  // for std::ostringstream

namespace meshpaint::cli {
namespace {

//! A label class's name and statistics; `stats` absent where nothing carries it.
struct Row
{
  int id = 0;
  std::string name;
  const LabelClass* named = nullptr;
  const LabelStats* stats = nullptr;
};

std::vector<Row> rows(const std::vector<LabelClass>& classes, const std::vector<LabelStats>& stats)
{
  std::map<int, Row> by_id;
  for (const LabelClass& c : classes)
    by_id[c.id] = Row{c.id, c.name, &c, nullptr};
  for (const LabelStats& s : stats) {
    Row& r = by_id[s.id];
    r.id = s.id;
    r.stats = &s;
    if (!r.named)
      r.name = s.id == 0 ? "unlabelled" : "";
  }
  std::vector<Row> out;
  for (const auto& [id, r] : by_id)
    out.push_back(r);
  return out;
}

std::string number(double v)
{
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

std::string triple(const Vec3& v) { return "(" + number(v[0]) + ", " + number(v[1]) + ", " + number(v[2]) + ")"; }

nlohmann::json json_triple(const Vec3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

} // namespace

int stats_command(const Argv& argv)
{
  Args args("stats", argv, {"--json", "--csv", "--no-weld"}, {"--labels", "--level", "--device", "--storage", "--import-array"});
  args.expect_positionals(1, 1, "MESH|PROJECT [--labels labels.json] [--json|--csv]");
  if (args.flag("--json") && args.flag("--csv"))
    throw InputError("--json and --csv exclude each other");
  const std::vector<LabelClass> table_labels =
    args.has("--labels") ? load_labels(args.value("--labels")) : std::vector<LabelClass>();
  const MeshOrProject input = open_mesh_or_project(args.positionals()[0], import_options(args));
  const std::vector<LabelClass> imported = imported_label_classes(input.mesh());
  const std::vector<LabelClass>& classes =
    args.has("--labels") ? table_labels : input.project ? input.project->labels : imported;
  const int level = input_level(args, input, 3);
  auto runtime = open_device(args);
  const auto surface = open_paint_surface(runtime, chosen_storage(args, *runtime), input, level);
  const PaintedSurface painted = surface->painted_surface();
  const std::vector<LabelStats> stats = label_stats(painted);
  const double total = surface_area(painted.surface);
  const std::vector<Row> table_rows = rows(classes, stats);

  if (args.flag("--json")) {
    nlohmann::json labels = nlohmann::json::array();
    for (const Row& r : table_rows) {
      nlohmann::json j = {{"id", r.id}, {"name", r.name}};
      j["colour"] = r.named ? json_triple(r.named->colour) : nlohmann::json(nullptr);
      j["vertices"] = r.stats ? r.stats->vertices : 0;
      j["area"] = r.stats ? r.stats->area : 0.0;
      j["area_fraction"] = r.stats && total > 0 ? r.stats->area / total : 0.0;
      j["centroid"] = r.stats ? json_triple(r.stats->centroid) : nlohmann::json(nullptr);
      j["bbox_min"] = r.stats ? json_triple(r.stats->bbox_min) : nlohmann::json(nullptr);
      j["bbox_max"] = r.stats ? json_triple(r.stats->bbox_max) : nlohmann::json(nullptr);
      labels.push_back(j);
    }
    const nlohmann::json out = {{"input", input.path}, {"level", level},
                                {"vertices", painted.surface.points.size()}, {"quads", painted.surface.quads.size()},
                                {"area", total}, {"labels", labels}};
    std::cout << out.dump() << "\n";
    return 0;
  }
  if (args.flag("--csv")) {
    std::cout << "id,name,vertices,area,area_fraction,centroid_x,centroid_y,centroid_z,min_x,min_y,min_z,max_x,max_y,"
                 "max_z\n";
    for (const Row& r : table_rows) {
      std::cout << r.id << "," << json_string(r.name) << "," << (r.stats ? r.stats->vertices : 0) << ","
                << number(r.stats ? r.stats->area : 0.0) << "," << number(r.stats && total > 0 ? r.stats->area / total : 0.0);
      for (const Vec3* v : {r.stats ? &r.stats->centroid : nullptr, r.stats ? &r.stats->bbox_min : nullptr,
                            r.stats ? &r.stats->bbox_max : nullptr})
        for (int a = 0; a < 3; ++a)
          std::cout << "," << (v ? number((*v)[a]) : "");
      std::cout << "\n";
    }
    return 0;
  }
  std::cout << "surface    " << input.path << ": level " << level << ", " << counted(painted.surface.points.size(), "vertex", "vertices", true)
            << ", " << counted(painted.surface.quads.size(), "quad", "quads", true) << ", area " << number(total) << "\n";
  Table table({"id", "name", "vertices", "area", "area %", "centroid", "bounds min", "bounds max"});
  for (const Row& r : table_rows)
    table.add({std::to_string(r.id), r.name, grouped(r.stats ? r.stats->vertices : 0),
               number(r.stats ? r.stats->area : 0.0),
               format_fixed(r.stats && total > 0 ? 100.0 * r.stats->area / total : 0.0, 2),
               r.stats ? triple(r.stats->centroid) : "-", r.stats ? triple(r.stats->bbox_min) : "-",
               r.stats ? triple(r.stats->bbox_max) : "-"});
  table.print(std::cout);
  return 0;
}

} // namespace meshpaint::cli
