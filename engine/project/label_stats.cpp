#include "project/label_stats.h"

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::sqrt
#include <map>       // for std::map

namespace meshpaint {
namespace {

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
  const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return 0.5 * std::sqrt(x * x + y * y + z * z);
}

double quad_area(const WeldedSurface& s, std::size_t q)
{
  const auto& c = s.quads[q];
  return triangle_area(s.points[c[0]], s.points[c[1]], s.points[c[2]]) +
         triangle_area(s.points[c[0]], s.points[c[2]], s.points[c[3]]);
}

} // namespace

double surface_area(const WeldedSurface& surface)
{
  double total = 0;
  for (std::size_t q = 0; q < surface.quads.size(); ++q)
    total += quad_area(surface, q);
  return total;
}

std::vector<LabelStats> label_stats(const PaintedSurface& painted)
{
  const WeldedSurface& s = painted.surface;
  std::vector<double> share(s.points.size(), 0.0);
  for (std::size_t q = 0; q < s.quads.size(); ++q) {
    const double a = quad_area(s, q) / 4;
    for (const int v : s.quads[q])
      share[std::size_t(v)] += a;
  }
  struct Sum
  {
    LabelStats stats;
    double weighted[3] = {0, 0, 0};
  };
  std::map<int, Sum> sums;
  for (std::size_t v = 0; v < s.points.size(); ++v) {
    const Vec3& p = s.points[v];
    const auto [it, fresh] = sums.try_emplace(painted.label[v]);
    LabelStats& l = it->second.stats;
    if (fresh) {
      l.id = painted.label[v];
      l.bbox_min = l.bbox_max = p;
    }
    ++l.vertices;
    l.area += share[v];
    for (int a = 0; a < 3; ++a) {
      it->second.weighted[a] += share[v] * p[a];
      l.bbox_min[a] = std::min(l.bbox_min[a], p[a]);
      l.bbox_max[a] = std::max(l.bbox_max[a], p[a]);
    }
  }
  std::vector<LabelStats> out;
  for (auto& [id, sum] : sums) {
    for (int a = 0; a < 3; ++a)
      sum.stats.centroid[a] = sum.stats.area > 0 ? float(sum.weighted[a] / sum.stats.area) : sum.stats.bbox_min[a];
    out.push_back(sum.stats);
  }
  return out;
}

} // namespace meshpaint
