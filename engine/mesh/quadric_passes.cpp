#include "mesh/quadric_passes.h"

#include <CGAL/boost/graph/Euler_operations.h> // for collapse_edge, does_satisfy_link_condition

#include <algorithm> // for std::nth_element, std::sort
#include <array>     // for std::array
#include <cmath>     // for std::sqrt
#include <cstdint>   // for std::uint32_t, std::uint8_t
#include <limits>    // for std::numeric_limits
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

using Point = CgalKernel::Point_3;
using Vector = CgalKernel::Vector_3;

//! A symmetric 4x4 plane quadric: the summed squared distances to its
//! planes, each weighted. a: the 3x3 part (xx xy xz yy yz zz), b, c.
struct Quadric
{
  std::array<double, 6> a{};
  Vector b{0, 0, 0};
  double c = 0;

  void add_plane(const Vector& n, const Point& on, double weight)
  {
    const double d = -(n.x() * on.x() + n.y() * on.y() + n.z() * on.z());
    a[0] += weight * n.x() * n.x();
    a[1] += weight * n.x() * n.y();
    a[2] += weight * n.x() * n.z();
    a[3] += weight * n.y() * n.y();
    a[4] += weight * n.y() * n.z();
    a[5] += weight * n.z() * n.z();
    b = b + weight * d * n;
    c += weight * d * d;
  }
  Quadric operator+(const Quadric& o) const
  {
    Quadric q;
    for (int k = 0; k < 6; ++k)
      q.a[k] = a[k] + o.a[k];
    q.b = b + o.b;
    q.c = c + o.c;
    return q;
  }
  double cost(const Point& p) const
  {
    const double x = p.x(), y = p.y(), z = p.z();
    return a[0] * x * x + 2 * a[1] * x * y + 2 * a[2] * x * z + a[3] * y * y + 2 * a[4] * y * z + a[5] * z * z +
           2 * (b.x() * x + b.y() * y + b.z() * z) + c;
  }
};

// Planes across border edges weigh this much more than faces of the same
// extent, so that a border moves only along itself.
constexpr double kBorderWeight = 100;
// cos 60 degrees: the largest turn of a face of a collapse's star.
constexpr double kMinNormalCosine = 0.5;
// Valence of the kept vertex beyond which a collapse is refused (slivers).
constexpr int kMaxValence = 24;

// Where the kept vertex goes: onto an end, named by its vertex index
// (an edge's halfedge may turn around in a collapse nearby, so "source"
// would not last), or the midpoint.
constexpr std::uint32_t kMidpoint = ~std::uint32_t(0);

struct Candidate
{
  float cost;
  std::uint32_t edge;
  std::uint32_t at; //!< vertex index, or kMidpoint
};

using QuadricMap = CgalMesh::Property_map<CgalMesh::Vertex_index, Quadric>;
using RefusedMap = CgalMesh::Property_map<CgalMesh::Edge_index, bool>;

// About this many of the candidates under the limit collapse in a pass (a
// tenth to a fifth, measured): when that would overshoot the budget, the
// pass goes in cost order.
constexpr double kCollapsedPerCandidate = 0.15;

//! Sums each vertex's plane quadrics into `q` (zero to begin with).
void add_vertex_quadrics(const CgalMesh& mesh, QuadricMap& q)
{
  for (const CgalMesh::Face_index f : mesh.faces()) {
    const CgalMesh::Halfedge_index h = mesh.halfedge(f);
    const CgalMesh::Vertex_index v[3] = {mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))};
    const Vector n = CGAL::cross_product(mesh.point(v[1]) - mesh.point(v[0]), mesh.point(v[2]) - mesh.point(v[0]));
    const double twice_area = std::sqrt(n.squared_length());
    if (twice_area == 0)
      continue;
    for (const CgalMesh::Vertex_index u : v)
      q[u].add_plane(n / twice_area, mesh.point(v[0]), 0.5 * twice_area);
  }
  for (const CgalMesh::Halfedge_index h : mesh.halfedges()) {
    if (!mesh.is_border(mesh.opposite(h)) || mesh.is_border(h))
      continue;
    const Point& s = mesh.point(mesh.source(h));
    const Vector along = mesh.point(mesh.target(h)) - s;
    const Vector face_normal =
        CGAL::cross_product(along, mesh.point(mesh.target(mesh.next(h))) - s);
    const Vector across = CGAL::cross_product(along, face_normal);
    const double length = std::sqrt(across.squared_length());
    if (length == 0)
      continue;
    for (const CgalMesh::Vertex_index u : {mesh.source(h), mesh.target(h)})
      q[u].add_plane(across / length, s, kBorderWeight * along.squared_length());
  }
}

//! Whether moving `moved` (and `other`, the edge's far end) to `p` keeps
//! every face of `moved`'s star that survives the collapse turned by at
//! most 60 degrees and not degenerate; counts the faces into `valence`.
bool star_keeps_its_faces(const CgalMesh& mesh, CgalMesh::Vertex_index moved, CgalMesh::Vertex_index other,
                          const Point& p, int& valence)
{
  for (const CgalMesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(moved), mesh)) {
    ++valence;
    if (mesh.is_border(h))
      continue;
    const CgalMesh::Vertex_index x = mesh.target(mesh.next(h)), y = mesh.source(h);
    if (x == other || y == other)
      continue;
    const Point& a = mesh.point(moved);
    const Vector before = CGAL::cross_product(mesh.point(x) - a, mesh.point(y) - a);
    const Vector after = CGAL::cross_product(mesh.point(x) - p, mesh.point(y) - p);
    const double dot = before * after;
    if (dot <= 0 || dot * dot <= kMinNormalCosine * kMinNormalCosine * before.squared_length() * after.squared_length())
      return false;
  }
  return true;
}

} // namespace

QuadricPasses reduce_in_passes(CgalMesh& mesh, std::size_t target_faces)
{
  QuadricPasses result;
  // On the mesh, so that collecting its garbage moves them along.
  QuadricMap quadrics = mesh.add_property_map<CgalMesh::Vertex_index, Quadric>("v:meshpaint_quadric").first;
  add_vertex_quadrics(mesh, quadrics);
  // Edges whose collapse was refused (a fold, a sliver, the link): left
  // out of their neighbours' comparison, lest they hold them back forever.
  RefusedMap refused = mesh.add_property_map<CgalMesh::Edge_index, bool>("e:meshpaint_refused", false).first;
  std::vector<char> border, kept_this_pass;
  std::vector<Candidate> candidates;
  std::vector<float> costs, cheapest;
  while (mesh.number_of_faces() > target_faces) {
    // Each pass walks every slot, removed ones too: once most are removed,
    // compact (the passes remove about a tenth of the faces each).
    if (mesh.number_of_removed_faces() > mesh.number_of_faces())
      mesh.collect_garbage();
    const std::size_t faces_before = mesh.number_of_faces();
    border.assign(mesh.num_vertices(), 0);
    kept_this_pass.resize(mesh.num_vertices());
    for (const CgalMesh::Halfedge_index h : mesh.halfedges())
      if (mesh.is_border(h))
        border[mesh.source(h)] = border[mesh.target(h)] = 1;

    candidates.clear();
    for (const CgalMesh::Edge_index e : mesh.edges()) {
      const CgalMesh::Halfedge_index h = mesh.halfedge(e);
      const CgalMesh::Vertex_index s = mesh.source(h), t = mesh.target(h);
      const bool border_edge = mesh.is_border(e);
      if (!border_edge && border[s] && border[t])
        continue; // would pinch the surface across
      const Quadric q = quadrics[s] + quadrics[t];
      Candidate best{0, std::uint32_t(e), kMidpoint};
      double cost = -1;
      auto consider = [&](std::uint32_t at, const Point& p) {
        const double c = q.cost(p);
        if (cost < 0 || c < cost) {
          cost = c;
          best.at = at;
        }
      };
      if (border_edge || !border[t])
        consider(std::uint32_t(s), mesh.point(s));
      if (border_edge || !border[s])
        consider(std::uint32_t(t), mesh.point(t));
      if (border_edge || (!border[s] && !border[t]))
        consider(kMidpoint, CGAL::midpoint(mesh.point(s), mesh.point(t)));
      best.cost = float(std::max(cost, 0.0));
      candidates.push_back(best);
    }
    if (candidates.empty())
      break;

    // The cheapest quarter may collapse. Where that would remove more than
    // is left to remove, cost order decides which go before the budget is
    // met; otherwise an edge goes if none at its ends is cheaper (edges
    // refused before do not count), in memory order, which keeps the
    // collapses' reads near each other instead of scattered by cost.
    const std::size_t quarter = (candidates.size() + 3) / 4;
    const bool in_cost_order = double(quarter) * kCollapsedPerCandidate > double(faces_before - target_faces) / 2;
    auto end = candidates.end();
    float limit = 0;
    if (in_cost_order) {
      const auto cheaper = [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; };
      end = candidates.begin() + std::ptrdiff_t(quarter);
      std::nth_element(candidates.begin(), end - 1, candidates.end(), cheaper);
      std::sort(candidates.begin(), end, cheaper);
      limit = end[-1].cost;
    } else {
      costs.resize(candidates.size());
      for (std::size_t i = 0; i < candidates.size(); ++i)
        costs[i] = candidates[i].cost;
      std::nth_element(costs.begin(), costs.begin() + std::ptrdiff_t(quarter - 1), costs.end());
      limit = costs[quarter - 1];
      cheapest.assign(mesh.num_vertices(), std::numeric_limits<float>::infinity());
      for (const Candidate& c : candidates) {
        const CgalMesh::Edge_index e(c.edge);
        if (refused[e])
          continue;
        float& at_source = cheapest[mesh.source(mesh.halfedge(e))];
        float& at_target = cheapest[mesh.target(mesh.halfedge(e))];
        at_source = std::min(at_source, c.cost);
        at_target = std::min(at_target, c.cost);
      }
    }

    // Only the kept vertex is marked: a collapse changes no other vertex's
    // quadric or point, so every other edge's cost stays exact.
    std::fill(kept_this_pass.begin(), kept_this_pass.end(), 0);
    for (auto c = candidates.begin(); c != end && mesh.number_of_faces() > target_faces; ++c) {
      const CgalMesh::Edge_index e(c->edge);
      if (c->cost > limit || mesh.is_removed(e))
        continue;
      const CgalMesh::Halfedge_index h = mesh.halfedge(e);
      const CgalMesh::Vertex_index s = mesh.source(h), t = mesh.target(h);
      if (kept_this_pass[s] || kept_this_pass[t] ||
          (!in_cost_order && (c->cost > cheapest[s] || c->cost > cheapest[t])))
        continue;
      const Point p = c->at == kMidpoint ? CGAL::midpoint(mesh.point(s), mesh.point(t))
                                         : mesh.point(CgalMesh::Vertex_index(c->at));
      int valence = 0;
      if (!star_keeps_its_faces(mesh, s, t, p, valence) || !star_keeps_its_faces(mesh, t, s, p, valence) ||
          valence - 4 > kMaxValence || !CGAL::Euler::does_satisfy_link_condition(e, mesh)) {
        refused[e] = true;
        continue;
      }
      const Quadric q = quadrics[s] + quadrics[t];
      const CgalMesh::Vertex_index kept = CGAL::Euler::collapse_edge(e, mesh);
      mesh.point(kept) = p;
      quadrics[kept] = q;
      kept_this_pass[kept] = 1;
    }
    ++result.passes;
    if (100 * (faces_before - mesh.number_of_faces()) < faces_before)
      break;
  }
  mesh.remove_property_map(quadrics);
  mesh.remove_property_map(refused);
  result.faces = mesh.number_of_faces();
  return result;
}

} // namespace meshpaint
