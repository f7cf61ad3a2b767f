#include "mesh/soup_import.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>     // for CGAL::Epick
#include <CGAL/Polygon_mesh_processing/connected_components.h>      // for connected_components
#include <CGAL/Polygon_mesh_processing/orientation.h>               // for is_outward_oriented
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>       // for orient_polygon_soup
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h> // for polygon_soup_to_polygon_mesh
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>       // for merge_duplicate_polygons_in_polygon_soup
#include <CGAL/Surface_mesh.h>                                      // for CGAL::Surface_mesh

#include <algorithm>     // for std::sort, std::adjacent_find, std::reverse
#include <cmath>         // for std::floor, std::fabs, std::isfinite
#include <cstdint>       // for std::uint64_t, std::uint32_t
#include <cstring>       // for std::memcpy
#include <functional>    // for std::hash
#include <map>           // for std::map
#include <numeric>       // for std::iota
#include <unordered_map> // for std::unordered_map
#include <utility>       // for std::pair

namespace meshpaint {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;

//! Kept points are hashed in cells of this many tolerances: a point looks
//! past its own cell only on the sides it lies within the tolerance of.
constexpr double kCellTolerances = 4;

struct Cell
{
  long long x, y, z;
  bool operator==(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CellHash
{
  std::size_t operator()(const Cell& c) const
  {
    return std::hash<long long>()(c.x * 73856093LL ^ c.y * 19349663LL ^ c.z * 83492791LL);
  }
};

//! Whether `polygons` already form an oriented manifold, on which CGAL's
//! orient_polygon_soup() would change nothing: no directed edge twice (so
//! no edge in three faces and no two faces across an edge that disagree),
//! and the corners around each vertex one fan; `closed_fan` says whose fan
//! closes (a vertex in no polygon counts as closed). Linear, on flat arrays: on
//! scans of millions of faces the orienter's maps take several times as
//! long, and most files are oriented manifolds already.
bool oriented_manifold(std::size_t points, const std::vector<Polygon>& polygons, std::vector<char>& closed_fan)
{
  closed_fan.assign(points, 1);
  // Corners grouped by their vertex (counting sort): each as (prev, next).
  std::vector<std::size_t> first(points + 1, 0);
  for (const Polygon& p : polygons)
    for (const std::size_t v : p)
      ++first[v + 1];
  for (std::size_t v = 0; v < points; ++v)
    first[v + 1] += first[v];
  std::vector<std::pair<std::size_t, std::size_t>> corners(first[points]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for (const Polygon& p : polygons)
    for (std::size_t k = 0; k < p.size(); ++k)
      corners[fill[p[k]]++] = {p[(k + p.size() - 1) % p.size()], p[(k + 1) % p.size()]};

  std::vector<char> seen;
  for (std::size_t v = 0; v < points; ++v) {
    const auto begin = corners.begin() + std::ptrdiff_t(first[v]), end = corners.begin() + std::ptrdiff_t(first[v + 1]);
    const std::size_t n = std::size_t(end - begin);
    if (n == 0)
      continue;
    // No edge out of v twice; sorted by next for the walk below.
    std::sort(begin, end, [](const auto& a, const auto& b) { return a.second < b.second; });
    for (auto c = begin; c + 1 < end; ++c)
      if (c->second == (c + 1)->second)
        return false;
    // Walk the fan: from a corner to the one across its edge out of v
    // (whose edge into v comes from that corner's next), both ways.
    const auto across_out = [&](std::size_t next) { // the corner whose prev is `next`
      for (auto c = begin; c != end; ++c)
        if (c->first == next)
          return std::size_t(c - begin);
      return n;
    };
    const auto across_in = [&](std::size_t prev) { // the corner whose next is `prev`
      const auto c = std::lower_bound(begin, end, prev, [](const auto& a, std::size_t x) { return a.second < x; });
      return c != end && c->second == prev ? std::size_t(c - begin) : n;
    };
    seen.assign(n, 0);
    std::size_t visited = 1;
    seen[0] = 1;
    std::size_t c = across_out(begin[0].second);
    for (; c < n && !seen[c]; c = across_out(begin[std::ptrdiff_t(c)].second)) {
      seen[c] = 1;
      ++visited;
    }
    closed_fan[v] = c < n; // back at the first corner
    for (std::size_t c = across_in(begin[0].first); c < n && !seen[c]; c = across_in(begin[std::ptrdiff_t(c)].first)) {
      seen[c] = 1;
      ++visited;
    }
    if (visited != n)
      return false;
  }
  return true;
}

//! The components of an oriented manifold's polygons (oriented_manifold()),
//! numbered from 0 in the order of their first polygons, into
//! `component_of`, and whether each is closed. In such a soup the polygons
//! around a vertex are one fan, joined across edges, so the components are
//! those of the shared vertices: one union-find pass instead of a CGAL mesh.
std::size_t manifold_components(const std::vector<Polygon>& polygons, const std::vector<char>& closed_fan,
                                std::vector<std::size_t>& component_of, std::vector<bool>& closed)
{
  std::vector<std::size_t> parent(closed_fan.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&](std::size_t v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Polygon& p : polygons)
    for (std::size_t k = 1; k < p.size(); ++k) {
      const std::size_t a = root(p[0]), b = root(p[k]);
      parent[std::max(a, b)] = std::min(a, b);
    }
  constexpr std::size_t kNone = std::size_t(-1);
  std::vector<std::size_t> number(parent.size(), kNone);
  closed.clear();
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    std::size_t& n = number[root(polygons[f][0])];
    if (n == kNone) {
      n = closed.size();
      closed.push_back(true);
    }
    component_of[f] = n;
  }
  for (std::size_t v = 0; v < parent.size(); ++v)
    if (!closed_fan[v])
      closed[number[root(v)]] = false; // an open fan is in some polygon
  return closed.size();
}

//! Which components face inward, of those `judged` (closed ones), by
//! CGAL's test (PMP::is_outward_oriented). That test decides at a
//! component's first vertex of greatest z from the triangles around it
//! alone; those triangles (each polygon fanned from its first corner, as
//! the whole component would be) make a small CGAL mesh per component,
//! where the whole component as one costs seconds on a scan of millions of
//! faces. Their points keep their order, so that the test finds the same
//! vertex. A star that is no disk is not judged.
std::vector<bool> inward_components(const std::vector<Point>& points, const std::vector<Polygon>& polygons,
                                    const std::vector<std::size_t>& component_of, const std::vector<bool>& judged)
{
  if (judged.empty())
    return {};
  const std::size_t none = points.size();
  std::vector<std::size_t> top(judged.size(), none);
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    std::size_t& t = top[component_of[f]];
    for (const std::size_t v : polygons[f])
      if (t == none || points[v].z() > points[t].z() || (points[v].z() == points[t].z() && v < t))
        t = v;
  }
  std::vector<std::vector<Polygon>> stars(judged.size());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const std::size_t c = component_of[f];
    const Polygon& p = polygons[f];
    for (std::size_t k = 1; judged[c] && k + 1 < p.size(); ++k)
      if (p[0] == top[c] || p[k] == top[c] || p[k + 1] == top[c])
        stars[c].push_back({p[0], p[k], p[k + 1]});
  }
  std::vector<bool> inward(judged.size(), false);
  for (std::size_t c = 0; c < judged.size(); ++c) {
    if (!judged[c])
      continue;
    std::vector<std::size_t> used;
    for (const Polygon& t : stars[c])
      used.insert(used.end(), t.begin(), t.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    const auto local = [&](std::size_t v) {
      return std::size_t(std::lower_bound(used.begin(), used.end(), v) - used.begin());
    };
    std::vector<Point> star_points;
    for (const std::size_t v : used)
      star_points.push_back(points[v]);
    for (Polygon& t : stars[c])
      for (std::size_t& v : t)
        v = local(v);
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(star_points, stars[c], mesh);
    const Mesh::Vertex_index v_top(Mesh::size_type(local(top[c])));
    inward[c] = mesh.number_of_faces() == stars[c].size() && !mesh.is_border(v_top) &&
                !PMP::internal::is_outward_oriented(v_top, mesh, CGAL::parameters::default_values());
  }
  return inward;
}

//! FNV-1a over 64-bit words: its offset basis and one step.
constexpr std::uint64_t kFnvBasis = 1469598103934665603ULL;
constexpr std::uint64_t fnv_step(std::uint64_t h, std::uint64_t x) { return (h ^ x) * 1099511628211ULL; }

//! Whether no two of `hashes` agree.
bool all_distinct(std::vector<std::uint64_t> hashes)
{
  std::sort(hashes.begin(), hashes.end());
  return std::adjacent_find(hashes.begin(), hashes.end()) == hashes.end();
}

//! A hash of a polygon's corners, sorted: the same for two polygons with
//! the same corners in any order or orientation.
std::uint64_t corner_set_hash(const Polygon& sorted)
{
  std::uint64_t h = kFnvBasis;
  for (const std::size_t v : sorted)
    h = fnv_step(h, std::uint64_t(v));
  return h;
}

//! Whether two polygons may have the same corners: two of their
//! corner_set_hash() values agree. False means no duplicate for certain, so
//! that CGAL's merge (whose ordered map of polygons is slow on millions)
//! runs only where it may find something.
bool may_have_duplicates(std::vector<std::uint64_t> hashes)
{
  return !all_distinct(std::move(hashes));
}

//! Whether each point lies on a border of the faces as listed: its faces'
//! edges out of it and into it differ (a soup's points all do, a scan's
//! inner vertices do not). Compared through sums of mixed ids, so one pass.
std::vector<bool> open_fans(std::size_t points, const std::vector<std::vector<int>>& faces)
{
  const auto mixed = [](std::uint64_t x) { // splitmix64's finaliser
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  };
  std::vector<std::uint64_t> out(points, 0), in(points, 0);
  std::vector<bool> used(points, false);
  for (const auto& f : faces)
    for (std::size_t k = 0; k < f.size(); ++k) {
      const auto v = std::size_t(f[k]);
      out[v] += mixed(std::uint64_t(f[(k + 1) % f.size()]));
      in[v] += mixed(std::uint64_t(f[(k + f.size() - 1) % f.size()]));
      used[v] = true;
    }
  std::vector<bool> open(points);
  for (std::size_t v = 0; v < points; ++v)
    open[v] = !used[v] || out[v] != in[v];
  return open;
}

//! Whether two of `points` may lie at one position: two hashes of their
//! coordinates agree (-0 taken as 0). False means no two coincide for
//! certain; on a closed scan that is all the weld needs to know, found by
//! a sort instead of millions of lookups in a hash grid.
bool may_coincide(const std::vector<Vec3>& points)
{
  std::vector<std::uint64_t> hashes(points.size());
  for (std::size_t v = 0; v < points.size(); ++v) {
    std::uint64_t h = kFnvBasis;
    for (int a = 0; a < 3; ++a) {
      const float x = points[v][std::size_t(a)] + 0.0f; // -0 + 0 is +0
      std::uint32_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = fnv_step(h, bits);
    }
    hashes[v] = h;
  }
  return !all_distinct(std::move(hashes));
}

//! For each point, in order, the first earlier kept point it joins, or the
//! point itself, which is then kept. A point joins a kept point at its very
//! position, or within `tolerance` when either lies on a border (`open`):
//! a dense scan's inner vertices can lie closer than the tolerance, and
//! joining them would tear the surface. Every point lies within the
//! tolerance of the one it joins.
std::vector<std::size_t> weld_targets(const std::vector<Vec3>& points, const std::vector<bool>& open, double tolerance)
{
  std::vector<std::size_t> target(points.size());
  std::iota(target.begin(), target.end(), std::size_t(0));
  const double cell = kCellTolerances * tolerance, tolerance2 = tolerance * tolerance;
  if (!(cell > 0) || !std::isfinite(cell))
    return target;
  if (std::find(open.begin(), open.end(), true) == open.end() && !may_coincide(points))
    return target; // only points at one position could join, and there are none
  constexpr std::size_t kNone = std::size_t(-1);
  std::unordered_map<Cell, std::size_t, CellHash> first_kept; // a cell's kept points, chained by next_kept
  first_kept.reserve(points.size());
  std::vector<std::size_t> next_kept(points.size(), kNone);
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Vec3& p = points[v];
    long long c[3];
    int lo[3], hi[3];
    bool fits = true;
    for (int a = 0; a < 3; ++a) {
      const double q = p[a] / cell, floor_q = std::floor(q);
      fits = fits && std::fabs(floor_q) < 4e18; // a cell number and its neighbour as a long long
      c[a] = fits ? (long long)floor_q : 0;
      lo[a] = (q - floor_q) * kCellTolerances <= 1 ? -1 : 0;
      hi[a] = (floor_q + 1 - q) * kCellTolerances <= 1 ? 1 : 0;
    }
    if (!fits)
      continue; // kept unwelded; such coordinates are refused later
    std::size_t best = kNone;
    for (int dx = lo[0]; dx <= hi[0]; ++dx)
      for (int dy = lo[1]; dy <= hi[1]; ++dy)
        for (int dz = lo[2]; dz <= hi[2]; ++dz) {
          const auto it = first_kept.find({c[0] + dx, c[1] + dy, c[2] + dz});
          for (std::size_t k = it == first_kept.end() ? kNone : it->second; k != kNone; k = next_kept[k]) {
            double d2 = 0;
            for (int a = 0; a < 3; ++a)
              d2 += (double(points[k][a]) - double(p[a])) * (double(points[k][a]) - double(p[a]));
            if (d2 <= tolerance2 && k < best && (d2 == 0 || open[v] || open[k]))
              best = k;
          }
        }
    if (best != kNone) {
      target[v] = best;
      continue;
    }
    auto [it, fresh] = first_kept.emplace(Cell{c[0], c[1], c[2]}, v);
    if (!fresh) {
      next_kept[v] = it->second;
      it->second = v;
    }
  }
  return target;
}

//! `values` (`k` per point) of the points that join at each kept point,
//! averaged in point order; `index` numbers the kept points.
std::vector<float> joined_means(const std::vector<float>& values, std::size_t k, const std::vector<std::size_t>& index,
                                std::size_t kept)
{
  std::vector<float> sum(kept * k, 0.f);
  std::vector<int> n(kept, 0);
  for (std::size_t v = 0; v < index.size(); ++v) {
    for (std::size_t a = 0; a < k; ++a)
      sum[index[v] * k + a] += values[v * k + a];
    ++n[index[v]];
  }
  for (std::size_t w = 0; w < kept; ++w)
    for (std::size_t a = 0; a < k; ++a)
      sum[w * k + a] /= float(n[w]);
  return sum;
}

//! Joins the soup's points closer than `tolerance` (weld_targets()): faces
//! name the kept points, colours and channel values take the mean of the
//! points joined, labels the most frequent id (the smallest of a tie).
//! Returns how many points were joined into others.
std::size_t weld_points(PolygonSoup& soup, double tolerance)
{
  const std::vector<std::size_t> target = weld_targets(soup.points, open_fans(soup.points.size(), soup.faces), tolerance);
  std::vector<std::size_t> index(target.size());
  std::size_t kept = 0;
  for (std::size_t v = 0; v < target.size(); ++v)
    index[v] = target[v] == v ? kept++ : index[target[v]];
  if (kept == soup.points.size())
    return 0;
  std::vector<Vec3> points(kept);
  for (std::size_t v = 0; v < target.size(); ++v)
    if (target[v] == v)
      points[index[v]] = soup.points[v];
  for (auto& f : soup.faces)
    for (int& v : f)
      v = int(index[std::size_t(v)]);
  if (!soup.colours.empty()) {
    std::vector<float> flat(soup.colours.size() * 3);
    for (std::size_t v = 0; v < soup.colours.size(); ++v)
      for (int a = 0; a < 3; ++a)
        flat[v * 3 + std::size_t(a)] = soup.colours[v][std::size_t(a)];
    const std::vector<float> mean = joined_means(flat, 3, index, kept);
    soup.colours.resize(kept);
    for (std::size_t w = 0; w < kept; ++w)
      soup.colours[w] = {mean[w * 3], mean[w * 3 + 1], mean[w * 3 + 2]};
  }
  for (ChannelArray& a : soup.channels)
    a.values = joined_means(a.values, std::size_t(a.components), index, kept);
  if (!soup.labels.empty()) {
    std::vector<std::pair<std::size_t, int>> votes(index.size()); // (kept point, id), sorted into runs
    for (std::size_t v = 0; v < index.size(); ++v)
      votes[v] = {index[v], soup.labels[v]};
    std::sort(votes.begin(), votes.end());
    std::vector<int> labels(kept);
    std::vector<std::size_t> most(kept, 0);
    for (std::size_t i = 0; i < votes.size();) {
      std::size_t j = i;
      while (j < votes.size() && votes[j] == votes[i])
        ++j;
      const std::size_t w = votes[i].first;
      if (j - i > most[w]) { // runs of one point come in increasing id: a tie keeps the smaller
        most[w] = j - i;
        labels[w] = votes[i].second;
      }
      i = j;
    }
    soup.labels = std::move(labels);
  }
  soup.points = std::move(points);
  return target.size() - kept;
}

//! The values of the imported vertices, `k` floats each: those of the
//! vertex each one came from (`origin`; orienting may copy vertices).
template <typename Origin>
std::vector<float> carried_values(std::size_t count, const float* values, std::size_t k, Origin origin)
{
  std::vector<float> out(count * k);
  for (std::size_t v = 0; v < count; ++v)
    for (std::size_t a = 0; a < k; ++a)
      out[v * k + a] = values[origin(v) * k + a];
  return out;
}

} // namespace

SoupSteps import_soup(PolygonSoup& soup, bool weld)
{
  SoupSteps steps;
  if (soup.points.empty() || soup.faces.empty())
    return steps;
  colours_from_faces(soup);
  const bool coloured = !soup.colours.empty();
  const bool labelled = !soup.labels.empty();

  if (weld) {
    steps.weld_tolerance = kWeldTolerance * diagonal_of(soup.points);
    steps.vertices_welded = weld_points(soup, steps.weld_tolerance);
  }
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for (const Vec3& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  std::vector<Polygon> polygons;
  polygons.reserve(soup.faces.size());
  for (const auto& f : soup.faces)
    polygons.emplace_back(f.begin(), f.end());

  // Faces that name a vertex twice (also once welding joined two corners).
  // Their sorted corners serve the duplicate check too.
  std::vector<Polygon> valid;
  valid.reserve(polygons.size());
  std::vector<std::uint64_t> hashes;
  hashes.reserve(polygons.size());
  Polygon sorted;
  for (Polygon& p : polygons) {
    sorted.assign(p.begin(), p.end());
    std::sort(sorted.begin(), sorted.end());
    if (p.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      ++steps.degenerate_faces_dropped;
    else {
      valid.push_back(std::move(p));
      hashes.push_back(corner_set_hash(sorted));
    }
  }
  polygons = std::move(valid);
  if (may_have_duplicates(std::move(hashes)))
    steps.duplicate_faces_dropped = PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  if (polygons.empty()) {
    soup.faces.clear();
    return steps;
  }

  const std::size_t before_points = points.size();
  std::vector<char> closed_fan;
  const bool oriented = oriented_manifold(points.size(), polygons, closed_fan);
  steps.oriented_manifold = oriented;
  const std::vector<Polygon> unoriented = oriented ? std::vector<Polygon>() : polygons;
  if (!oriented)
    PMP::orient_polygon_soup(points, polygons);
  steps.vertices_cut = points.size() - before_points;
  // A cut vertex is a copy of one that was there; find it by position to
  // recognise the faces that were turned.
  std::map<Point, std::size_t> original;
  if (steps.vertices_cut > 0)
    for (std::size_t v = 0; v < before_points; ++v)
      original.emplace(points[v], v);
  const auto origin = [&](std::size_t v) { return v < before_points ? v : original.at(points[v]); };
  for (std::size_t f = 0; f < polygons.size() && !oriented; ++f) {
    const Polygon& p = polygons[f];
    const Polygon& q = unoriented[f];
    bool same = p.size() == q.size();
    for (std::size_t k = 0; same && k < p.size(); ++k)
      same = origin(p[k]) == q[k];
    steps.faces_flipped += same ? 0 : 1;
  }

  std::vector<std::size_t> component_of(polygons.size(), 0);
  std::size_t components = 0;
  std::vector<bool> closed;
  if (oriented)
    components = manifold_components(polygons, closed_fan, component_of, closed);
  else {
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    if (mesh.number_of_faces() == polygons.size()) {
      auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
      components = PMP::connected_components(mesh, fcc);
      for (const auto f : mesh.faces())
        component_of[std::size_t(f)] = fcc[f];
    }
    closed.assign(components, true);
    for (const auto h : mesh.halfedges())
      if (mesh.is_border(h))
        closed[component_of[std::size_t(mesh.face(mesh.opposite(h)))]] = false;
  }
  std::vector<bool> cut(components, false);
  for (std::size_t f = 0; f < polygons.size(); ++f)
    for (const std::size_t v : polygons[f])
      if (v >= before_points && components > 0)
        cut[component_of[f]] = true;
  std::vector<bool> judged(components);
  for (std::size_t c = 0; c < components; ++c) {
    steps.nonorientable_components += cut[c] ? 1 : 0;
    judged[c] = closed[c] && !cut[c];
  }
  const std::vector<bool> inward = inward_components(points, polygons, component_of, judged);
  steps.components_turned_outward = std::size_t(std::count(inward.begin(), inward.end(), true));
  for (std::size_t f = 0; f < polygons.size(); ++f)
    if (components > 0 && inward[component_of[f]])
      std::reverse(polygons[f].begin(), polygons[f].end());

  soup.points.resize(points.size());
  for (std::size_t v = 0; v < points.size(); ++v)
    soup.points[v] = {float(points[v].x()), float(points[v].y()), float(points[v].z())};
  if (coloured) {
    const std::vector<float> flat = carried_values(points.size(), soup.colours[0].data(), 3, origin);
    soup.colours.resize(points.size());
    for (std::size_t v = 0; v < points.size(); ++v)
      soup.colours[v] = {flat[v * 3], flat[v * 3 + 1], flat[v * 3 + 2]};
  }
  for (ChannelArray& a : soup.channels)
    a.values = carried_values(points.size(), a.values.data(), std::size_t(a.components), origin);
  if (labelled) {
    std::vector<int> labels(points.size());
    for (std::size_t v = 0; v < points.size(); ++v)
      labels[v] = soup.labels[origin(v)];
    soup.labels = std::move(labels);
  }
  soup.faces.assign(polygons.size(), {});
  for (std::size_t f = 0; f < polygons.size(); ++f)
    soup.faces[f].assign(polygons[f].begin(), polygons[f].end());
  soup.face_colours.clear();
  return steps;
}

} // namespace meshpaint
