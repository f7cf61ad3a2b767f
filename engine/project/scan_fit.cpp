#include "project/scan_fit.h"

#include "atlas/weld.h"
#include "core/errors.h"
#include "core/parallel_for.h"
#include "mesh/spatial_order.h"

#include <algorithm> // for std::max, std::max_element
#include <cmath>     // for std::sqrt, std::isfinite, std::abs
#include <optional>  // for std::optional

namespace meshpaint {
namespace {

Vec3 xyz(const Float4& t) { return {t[0], t[1], t[2]}; }

//! Points one thread takes at least, and points between two words of progress.
constexpr std::size_t kPointsPerThread = 4096, kPointsPerBlock = 1 << 16;

//! Halvings of a folding step before it is dropped.
constexpr int kMaxShortenings = 4;
//! Rounds of dropping the steps that still fold a quad.
constexpr int kDropRounds = 3;

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

//! Whether the finest quad (i, j) of patch p faces, by its diagonals,
//! against the sum of its corners' limit normals.
bool quad_folds(const LevelLayout& l, const std::vector<Float4>& limit, const std::vector<Float4>& normals, int p,
                int i, int j)
{
  const std::size_t a = l.index(p, i, j), b = l.index(p, i + 1, j), c = l.index(p, i + 1, j + 1),
                    d = l.index(p, i, j + 1);
  const Vec3 face = cross(sub(xyz(limit[c]), xyz(limit[a])), sub(xyz(limit[d]), xyz(limit[b])));
  const Vec3 n{normals[a][0] + normals[b][0] + normals[c][0] + normals[d][0],
               normals[a][1] + normals[b][1] + normals[c][1] + normals[d][1],
               normals[a][2] + normals[b][2] + normals[c][2] + normals[d][2]};
  return dot(face, n) < 0;
}

//! The patches with a folded finest quad.
std::vector<int> folded_patches(const LevelLayout& l, const std::vector<Float4>& limit,
                                const std::vector<Float4>& normals)
{
  std::vector<int> folded;
  for (int p = 0; p < l.patches; ++p) {
    bool fold = false;
    for (int j = 0; j < l.n && !fold; ++j)
      for (int i = 0; i < l.n && !fold; ++i)
        fold = quad_folds(l, limit, normals, p, i, j);
    if (fold)
      folded.push_back(p);
  }
  return folded;
}

//! Grows the marked welded vertices by the quads they touch.
void grow_marks(const LevelLayout& l, const std::vector<int>& map, std::vector<char>& marked)
{
  const std::vector<char> seed = marked;
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.n; ++j)
      for (int i = 0; i < l.n; ++i) {
        const std::size_t c[4] = {std::size_t(map[l.index(p, i, j)]), std::size_t(map[l.index(p, i + 1, j)]),
                                  std::size_t(map[l.index(p, i + 1, j + 1)]), std::size_t(map[l.index(p, i, j + 1)])};
        if (seed[c[0]] || seed[c[1]] || seed[c[2]] || seed[c[3]])
          for (const std::size_t w : c)
            marked[w] = 1;
      }
}

//! Shortens the steps that turn over a finest quad that did not fold
//! before them (`was_folded`, per quad): halves them within one quad of
//! it, or with `drop` sets them to zero within two. False when no quad
//! newly folds.
bool shorten_folding_steps(const LevelLayout& l, const std::vector<int>& map, const std::vector<Float4>& limit,
                           const std::vector<Float4>& normals, const std::vector<char>& was_folded, bool drop,
                           std::vector<float>& step)
{
  std::vector<char> marked(step.size(), 0);
  bool any = false;
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.n; ++j)
      for (int i = 0; i < l.n; ++i) {
        const std::size_t q = (std::size_t(p) * std::size_t(l.n) + std::size_t(j)) * std::size_t(l.n) + std::size_t(i);
        if (was_folded[q] || !quad_folds(l, limit, normals, p, i, j))
          continue;
        any = true;
        for (const std::size_t t : {l.index(p, i, j), l.index(p, i + 1, j), l.index(p, i + 1, j + 1), l.index(p, i, j + 1)})
          marked[std::size_t(map[t])] = 1;
      }
  for (int ring = 0; ring < (drop ? 2 : 1); ++ring)
    grow_marks(l, map, marked);
  for (std::size_t w = 0; w < step.size(); ++w)
    if (marked[w])
      step[w] *= drop ? 0.f : 0.5f;
  return any;
}

//! Per finest quad (patch-major, row by row), whether it folds.
std::vector<char> folded_quads(const LevelLayout& l, const std::vector<Float4>& limit,
                               const std::vector<Float4>& normals)
{
  std::vector<char> folded(std::size_t(l.patches) * std::size_t(l.n) * std::size_t(l.n));
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.n; ++j)
      for (int i = 0; i < l.n; ++i)
        folded[(std::size_t(p) * std::size_t(l.n) + std::size_t(j)) * std::size_t(l.n) + std::size_t(i)] =
          quad_folds(l, limit, normals, p, i, j);
  return folded;
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
  // Asked along a Morton curve: a scan's vertices in file order jump about
  // the index, and on millions of them the misses dominate.
  const std::vector<std::size_t> order = morton_order(from);
  std::vector<double> distance(from.size());
  parallel_for(from.size(), kPointsPerThread, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t k = order[i];
      distance[k] = length(sub(to.closest_point(from[k]), from[k]));
    }
  });
  // Summed in order, so the result does not depend on the threads.
  FitError e;
  double sum2 = 0;
  for (std::size_t k = 0; k < from.size(); ++k) {
    const Vec3& p = from[k];
    const double d = distance[k];
    sum2 += d * d;
    if (d > e.max) {
      e.max = d;
      e.worst = p;
    }
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
  std::unique_ptr<SurfaceQuery> own_query;
  if (!options.scan_query) {
    say("indexing the scan: " + std::to_string(scan.face_count()) + " faces");
    own_query = make_query(scan.points, triangles_of(scan));
  }
  const SurfaceQuery* scan_query = options.scan_query ? options.scan_query : own_query.get();
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
    std::vector<char> missed(welded, 0);
    // In blocks, so that progress is told between them.
    for (std::size_t block = 0; block < welded; block += kPointsPerBlock) {
      task->step(block);
      const std::size_t block_end = std::min(welded, block + kPointsPerBlock);
      parallel_for(block_end - block, kPointsPerThread, [&](std::size_t begin, std::size_t end) {
        for (std::size_t w = block + begin; w < block + end; ++w) {
          const Vec3 p = xyz(limit[first[w]]), n = xyz(normals[first[w]]);
          const Vec3 closest = scan_query->closest_point(p);
          const Vec3 to = sub(closest, p);
          const float d = length(to);
          Vec3 target = closest;
          // Where the closest point lies on the normal line already, it is the hit.
          if (d > 0 && std::abs(dot(to, n)) < 0.999f * d) {
            bool miss = false;
            target = normal_target(*scan_query, p, n, closest, std::max(4 * d, min_reach), miss);
            missed[w] = miss;
          }
          delta[w] = sub(target, p);
        }
      });
    }
    for (const char m : missed)
      report.ray_misses += m;
    task->step(welded);
    task.reset();
    // A step longer than the quads it moves can turn them over (where the
    // scan bends more sharply than the limit surface, or the normal line
    // hits it far off): such steps are halved until no quad folds that did
    // not fold before, and after kMaxShortenings halvings dropped around
    // the quads that still fold (up to kDropRounds times, as each limit
    // point depends on the control points one ring around it).
    const std::vector<char> was_folded = folded_quads(l, limit, normals);
    std::vector<float> step(welded, 1.f);
    const std::vector<Float4> start = control;
    for (int round = 0;; ++round) {
      for (std::size_t t = 0; t < map.size(); ++t) {
        const std::size_t w = std::size_t(map[t]);
        for (int a = 0; a < 3; ++a)
          control[t][a] = start[t][a] + step[w] * delta[w][a];
      }
      for (const Float4& c : control)
        for (int a = 0; a < 3; ++a)
          if (!std::isfinite(c[a]) || std::abs(c[a]) > kMaxCoordinate)
            throw InputError(scan.name + ": the fit does not converge to finite positions (pass " +
                             std::to_string(pass + 1) + ")");
      atlas.write_positions(level, control);
      if (round == kMaxShortenings + kDropRounds ||
          !shorten_folding_steps(l, map, atlas.read_limit_positions(), atlas.read_limit_normals(), was_folded,
                                 round >= kMaxShortenings, step))
        break;
    }
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

  report.folded = folded_patches(l, limit, atlas.read_limit_normals());
  const std::vector<double> area_after = patch_areas(l, limit);
  for (int p = 0; p < l.patches; ++p) {
    const double ratio = area_after[std::size_t(p)] / std::max(area_before[std::size_t(p)], 1e-300);
    if (ratio > 4 || ratio < 0.25)
      report.stretched.push_back(p);
  }
  return report;
}

} // namespace meshpaint
