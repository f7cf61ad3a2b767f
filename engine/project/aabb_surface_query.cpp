#include "project/aabb_surface_query.h"

#include "mesh/spatial_order.h"

#include <CGAL/AABB_traits.h>             // for CGAL::AABB_traits
#include <CGAL/AABB_tree.h>               // for CGAL::AABB_tree
#include <CGAL/AABB_triangle_primitive.h> // for CGAL::AABB_triangle_primitive
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h> // for CGAL::Epick

#include <cmath>    // for std::sqrt
#include <iterator> // for std::back_inserter
#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

namespace meshpaint {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point point(const Vec3& v) { return {v[0], v[1], v[2]}; }
Vec3 vec(const Point& p) { return {float(p.x()), float(p.y()), float(p.z())}; }

class AabbQuery : public SurfaceQuery
{
public:
  AabbQuery(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles)
  {
    // The tree's leaves read their triangles from triangles_: stored along
    // a Morton curve, a query's leaves lie near each other in memory
    // rather than spread over a scan's whole file order.
    std::vector<Vec3> centres(triangles.size());
    for (std::size_t k = 0; k < triangles.size(); ++k)
      for (int a = 0; a < 3; ++a)
        centres[k][std::size_t(a)] = (points[std::size_t(triangles[k][0])][std::size_t(a)] +
                                      points[std::size_t(triangles[k][1])][std::size_t(a)] +
                                      points[std::size_t(triangles[k][2])][std::size_t(a)]) / 3;
    const std::vector<std::size_t> order = morton_order(centres);
    centres = {};
    triangles_.reserve(triangles.size());
    for (const std::size_t k : order) {
      const auto& t = triangles[k];
      const Triangle tri(point(points[std::size_t(t[0])]), point(points[std::size_t(t[1])]),
                         point(points[std::size_t(t[2])]));
      if (!tri.is_degenerate()) {
        triangles_.push_back(tri);
        ids_.push_back(int(k));
      }
    }
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.build();
    // Built now, not on the first query, so that queries only read.
    tree_.accelerate_distance_queries();
  }

  Vec3 closest_point(const Vec3& p) const override
  {
    if (triangles_.empty())
      return p;
    return vec(tree_.closest_point(point(p)));
  }

  int closest_triangle(const Vec3& p, Vec3& closest) const override
  {
    if (triangles_.empty()) {
      closest = p;
      return -1;
    }
    const auto found = tree_.closest_point_and_primitive(point(p));
    closest = vec(found.first);
    return ids_[std::size_t(found.second - triangles_.cbegin())];
  }

  bool first_hit(const Vec3& a, const Vec3& b, Vec3& hit) const override
  {
    const Point from = point(a), to = point(b);
    if (triangles_.empty() || from == to)
      return false;
    // The triangles that the segment meets: the tree walks only the boxes
    // along it, where a ray would go on through the scan until it met one
    // (through a bone to its far wall, for every point aimed inwards). Each
    // is then met by the ray from `a`, as the ray's own walk would meet it,
    // and the nearest is kept.
    thread_local std::vector<Primitive::Id> met;
    met.clear();
    tree_.all_intersected_primitives(Kernel::Segment_3(from, to), std::back_inserter(met));
    const Kernel::Ray_3 ray(from, to);
    bool found = false;
    double nearest = 0;
    Point at = CGAL::ORIGIN; // read only once found
    for (const Primitive::Id& triangle : met) {
      const auto crossing = CGAL::intersection(ray, *triangle);
      if (!crossing)
        continue;
      Point p;
      if (const Point* q = boost::get<Point>(&*crossing))
        p = *q;
      else if (const Kernel::Segment_3* s = boost::get<Kernel::Segment_3>(&*crossing))
        p = CGAL::squared_distance(from, s->source()) <= CGAL::squared_distance(from, s->target()) ? s->source()
                                                                                                    : s->target();
      else
        continue;
      const double d = CGAL::squared_distance(from, p);
      if (!found || d < nearest) {
        found = true;
        nearest = d;
        at = p;
      }
    }
    if (!found || nearest > CGAL::squared_distance(from, to))
      return false;
    hit = vec(at);
    return true;
  }

private:
  std::vector<Triangle> triangles_;
  std::vector<int> ids_; //!< per triangle of the tree: its index as given
  Tree tree_;
};

} // namespace

SurfaceQueryFactory aabb_surface_queries()
{
  return [](const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles) {
    return std::unique_ptr<SurfaceQuery>(new AabbQuery(points, triangles));
  };
}

} // namespace meshpaint
