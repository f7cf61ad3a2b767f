#include "project/scan_fit.h"

#include "atlas/weld.h"
#include "core/errors.h"

#include <algorithm> // for std::max, std::max_element
#include <cmath>     // for std::sqrt, std::isfinite, std::abs
#include <optional>  // for std::optional

namespace meshpaint {
namespace {

Vec3 xyz(const Float4& t) { return {t[0], t[1], t[2]}; }

//! Where the normal line through `p` meets the scan: the closer hit of the
//! two directions within `reach`, else the closest point `fallback`.
Vec3 normal_target(const SurfaceQuery& scan, const Vec3& p, const Vec3& n, const Vec3& closest, float reach,
                   bool& missed)
{
  Vec3 best = closest;
  float best_d = -1.f;
  for (const float s : {1.f, -1.f}) {
    const Vec3 end{p[0] + s * reach * n[0], p[1] + s * reach * n[1], p[2] + s * reach * n[2]};
    Vec3 hit;
    if (scan.first_hit(p, end, hit)) {
      const float d = length(sub(hit, p));
      if (best_d < 0 || d < best_d) {
        best = hit;
        best_d = d;
      }
    }
  }
  missed = best_d < 0;
  return best;
}

//! Per patch, the area of its finest quads in `limit` (texels, patch-major).
std::vector<double> patch_areas(const LevelLayout& l, const std::vector<Float4>& limit)
{
  std::vector<double> area(std::size_t(l.patches), 0.0);
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.n; ++j)
      for (int i = 0; i < l.n; ++i) {
        const Vec3 a = xyz(limit[l.index(p, i, j)]), b = xyz(limit[l.index(p, i + 1, j)]);
        const Vec3 c = xyz(limit[l.index(p, i + 1, j + 1)]), d = xyz(limit[l.index(p, i, j + 1)]);
        area[std::size_t(p)] += 0.5 * length(cross(sub(c, a), sub(d, b)));
      }
  return area;
}

} // namespace

std::vector<std::array<int, 3>> triangles_of(const BaseMesh& mesh)
{
  std::vector<std::array<int, 3>> t;
  t.reserve(mesh.face_vertices.size());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const int* v = &mesh.face_vertices[std::size_t(mesh.face_offsets[f])];
    for (int k = 1; k + 1 < mesh.face_sizes[f]; ++k)
      t.push_back({v[0], v[k], v[k + 1]});
  }
  return t;
}

double scan_area(const BaseMesh& scan)
{
  double area = 0;
  for (const auto& t : triangles_of(scan)) {
    double e[2][3];
    for (int k = 0; k < 2; ++k)
      for (int a = 0; a < 3; ++a)
        e[k][a] = double(scan.points[std::size_t(t[std::size_t(k + 1)])][a]) - double(scan.points[std::size_t(t[0])][a]);
    const double c[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                         e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    area += 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  }
  return area;
}

FitError surface_distance(const SurfaceQuery& to, const std::vector<Vec3>& from)
{
  FitError e;
  double sum2 = 0;
  for (const Vec3& p : from) {
    const double d = length(sub(to.closest_point(p), p));
    sum2 += d * d;
    e.max = std::max(e.max, d);
  }
  e.rms = from.empty() ? 0.0 : std::sqrt(sum2 / double(from.size()));
  return e;
}

FitReport fit_atlas(Atlas& atlas, const BaseMesh& scan, const SurfaceQueryFactory& make_query,
                    const FitOptions& options)
{
  const auto say = [&](const std::string& line) { note(options.progress, line); };
  const int level = atlas.max_level();
  const LevelLayout l = atlas.layout(level);
  const std::vector<int> map = weld_map(atlas.topology(), l);
  const std::size_t welded = std::size_t(*std::max_element(map.begin(), map.end())) + 1;
  // The first texel of each welded vertex speaks for all its copies, which
  // hold the same limit values bit for bit.
  std::vector<std::size_t> first(welded, map.size());
  for (std::size_t t = map.size(); t-- > 0;)
    first[std::size_t(map[t])] = t;

  FitReport report;
  report.diagonal = scan.diagonal();
  // A scan without area (its faces on a line or at a point) has no normals
  // to fit along: the surface would collapse instead of fitting.
  if (!(scan_area(scan) > kMinScanArea * report.diagonal * report.diagonal))
    throw InputError(scan.name + ": the scan has no area (its faces lie on a line or at a point): nothing to fit to");
  report.points = welded;
  say("indexing the scan: " + std::to_string(scan.face_count()) + " faces");
  const std::unique_ptr<SurfaceQuery> scan_query = make_query(scan.points, triangles_of(scan));
  const float min_reach = float(1e-3 * report.diagonal);

  atlas.subdivide(1, level);
  std::vector<Float4> control = atlas.read_positions(level);
  const std::vector<double> area_before = patch_areas(l, atlas.read_limit_positions());
  std::vector<Vec3> delta(welded);
  for (int pass = 0; pass < options.passes; ++pass) {
    const std::vector<Float4> limit = atlas.read_limit_positions();
    const std::vector<Float4> normals = atlas.read_limit_normals();
    report.ray_misses = 0;
    std::optional<ProgressTask> task;
    task.emplace(options.progress, "pass " + std::to_string(pass + 1) + " of " + std::to_string(options.passes),
                 welded);
    for (std::size_t w = 0; w < welded; ++w) {
      if (w % 1024 == 0)
        task->step(w);
      const Vec3 p = xyz(limit[first[w]]), n = xyz(normals[first[w]]);
      const Vec3 closest = scan_query->closest_point(p);
      const Vec3 to = sub(closest, p);
      const float d = length(to);
      Vec3 target = closest;
      // Where the closest point lies on the normal line already, it is the hit.
      if (d > 0 && std::abs(dot(to, n)) < 0.999f * d) {
        bool missed = false;
        target = normal_target(*scan_query, p, n, closest, std::max(4 * d, min_reach), missed);
        report.ray_misses += missed;
      }
      delta[w] = sub(target, p);
    }
    task->step(welded);
    task.reset();
    for (std::size_t t = 0; t < map.size(); ++t)
      for (int a = 0; a < 3; ++a)
        control[t][a] += delta[std::size_t(map[t])][a];
    for (const Float4& c : control)
      for (int a = 0; a < 3; ++a)
        if (!std::isfinite(c[a]) || std::abs(c[a]) > kMaxCoordinate)
          throw InputError(scan.name + ": the fit does not converge to finite positions (pass " +
                           std::to_string(pass + 1) + ")");
    atlas.write_positions(level, control);
    say("pass " + std::to_string(pass + 1) + " of " + std::to_string(options.passes) + ": " + std::to_string(welded) +
        " points moved, " + std::to_string(report.ray_misses) + " to the closest point (the normal missed the scan)");
  }

  // Distances both ways, over the fitted limit surface as triangles.
  say("measuring the fit");
  const std::vector<Float4> limit = atlas.read_limit_positions();
  const WeldedSurface fitted = weld(atlas.topology(), l, limit, nullptr);
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(2 * fitted.quads.size());
  for (const auto& q : fitted.quads) {
    triangles.push_back({q[0], q[1], q[2]});
    triangles.push_back({q[0], q[2], q[3]});
  }
  const std::unique_ptr<SurfaceQuery> surface_query = make_query(fitted.points, triangles);
  report.scan_to_surface = surface_distance(*surface_query, scan.points);
  report.surface_to_scan = surface_distance(*scan_query, fitted.points);

  const std::vector<Float4> normals = atlas.read_limit_normals();
  const std::vector<double> area_after = patch_areas(l, limit);
  for (int p = 0; p < l.patches; ++p) {
    bool folded = false;
    for (int j = 0; j < l.n && !folded; ++j)
      for (int i = 0; i < l.n && !folded; ++i) {
        const std::size_t a = l.index(p, i, j), b = l.index(p, i + 1, j), c = l.index(p, i + 1, j + 1),
                          d = l.index(p, i, j + 1);
        const Vec3 face = cross(sub(xyz(limit[c]), xyz(limit[a])), sub(xyz(limit[d]), xyz(limit[b])));
        const Vec3 n{normals[a][0] + normals[b][0] + normals[c][0] + normals[d][0],
                     normals[a][1] + normals[b][1] + normals[c][1] + normals[d][1],
                     normals[a][2] + normals[b][2] + normals[c][2] + normals[d][2]};
        folded = dot(face, n) < 0;
      }
    if (folded)
      report.folded.push_back(p);
    const double ratio = area_after[std::size_t(p)] / std::max(area_before[std::size_t(p)], 1e-300);
    if (ratio > 4 || ratio < 0.25)
      report.stretched.push_back(p);
  }
  return report;
}

} // namespace meshpaint
