#include "mesh/soup_import.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>     // for CGAL::Epick
#include <CGAL/Polygon_mesh_processing/connected_components.h>      // for connected_components
#include <CGAL/Polygon_mesh_processing/orientation.h>               // for is_outward_oriented
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>       // for orient_polygon_soup
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h> // for polygon_soup_to_polygon_mesh
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>       // for merge_duplicate_points/polygons
#include <CGAL/Surface_mesh.h>                                      // for CGAL::Surface_mesh

#include <algorithm> // for std::min, std::max, std::reverse
#include <cmath>     // for std::floor, std::sqrt, std::fabs, std::isfinite
#include <map>       // for std::map
#include <set>       // for std::set
#include <tuple>     // for std::tuple

namespace meshpaint {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;

//! Points within `tolerance` of one another that fall into one grid cell
//! take that cell's first point, so that CGAL's exact merge joins them.
std::size_t snap_to_first_in_cell(std::vector<Point>& points, double tolerance)
{
  if (!(tolerance > 0) || !std::isfinite(tolerance))
    return 0;
  std::map<std::tuple<long long, long long, long long>, std::size_t> first;
  std::size_t snapped = 0;
  for (std::size_t v = 0; v < points.size(); ++v) {
    double q[3];
    bool fits = true;
    for (int a = 0; a < 3; ++a) {
      q[a] = std::floor(points[v][a] / tolerance);
      fits = fits && std::fabs(q[a]) < 9e18; // a cell number as a long long; the rest is refused later
    }
    if (!fits)
      continue;
    const auto [it, fresh] = first.emplace(std::make_tuple((long long)q[0], (long long)q[1], (long long)q[2]), v);
    if (!fresh && points[it->second] != points[v]) {
      points[v] = points[it->second];
      ++snapped;
    }
  }
  return snapped;
}

//! Per-vertex values, `k` floats each, summed by position before welding.
using PositionSums = std::map<Point, std::pair<std::vector<float>, int>>;

PositionSums sums_by_position(const std::vector<Point>& points, const float* values, std::size_t k)
{
  PositionSums sums;
  for (std::size_t v = 0; v < points.size(); ++v) {
    auto& [s, n] = sums.emplace(points[v], std::make_pair(std::vector<float>(k, 0.f), 0)).first->second;
    for (std::size_t a = 0; a < k; ++a)
      s[a] += values[v * k + a];
    ++n;
  }
  return sums;
}

//! The values of the imported vertices: with welding, the mean over the
//! vertices merged at each position; without, those of the vertex each one
//! came from (`origin`).
template <typename Origin>
std::vector<float> carried_values(const std::vector<Point>& points, const float* values, std::size_t k, bool weld,
                                  const PositionSums& sums, Origin origin)
{
  std::vector<float> out(points.size() * k);
  for (std::size_t v = 0; v < points.size(); ++v)
    for (std::size_t a = 0; a < k; ++a) {
      if (!weld) {
        out[v * k + a] = values[origin(v) * k + a];
        continue;
      }
      const auto& [s, n] = sums.at(points[v]);
      out[v * k + a] = s[a] / float(n);
    }
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

  std::vector<Point> points;
  points.reserve(soup.points.size());
  for (const Vec3& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  std::vector<Polygon> polygons;
  polygons.reserve(soup.faces.size());
  for (const auto& f : soup.faces)
    polygons.emplace_back(f.begin(), f.end());
  PositionSums colour_sums;                  // by position: colours of the vertices merged there
  std::vector<PositionSums> channel_sums(soup.channels.size()); // and so for each channel array
  std::map<Point, std::map<int, int>> label_votes; // by position: label ids of the vertices merged there

  if (weld) {
    steps.weld_tolerance = kWeldTolerance * diagonal_of(soup.points);
    snap_to_first_in_cell(points, steps.weld_tolerance);
    if (coloured)
      colour_sums = sums_by_position(points, soup.colours[0].data(), 3);
    for (std::size_t c = 0; c < soup.channels.size(); ++c)
      channel_sums[c] = sums_by_position(points, soup.channels[c].values.data(),
                                         std::size_t(soup.channels[c].components));
    if (labelled)
      for (std::size_t v = 0; v < points.size(); ++v)
        ++label_votes[points[v]][soup.labels[v]];
    steps.vertices_welded = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  }

  // Faces that name a vertex twice (also once welding joined two corners).
  std::vector<Polygon> valid;
  valid.reserve(polygons.size());
  for (Polygon& p : polygons) {
    const std::set<std::size_t> distinct(p.begin(), p.end());
    if (p.size() < 3 || distinct.size() != p.size())
      ++steps.degenerate_faces_dropped;
    else
      valid.push_back(std::move(p));
  }
  polygons = std::move(valid);
  steps.duplicate_faces_dropped = PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  if (polygons.empty()) {
    soup.faces.clear();
    return steps;
  }

  const std::size_t before_points = points.size();
  const std::vector<Polygon> unoriented = polygons;
  PMP::orient_polygon_soup(points, polygons);
  steps.vertices_cut = points.size() - before_points;
  // A cut vertex is a copy of one that was there; find it by position to
  // recognise the faces that were turned.
  std::map<Point, std::size_t> original;
  if (steps.vertices_cut > 0)
    for (std::size_t v = 0; v < before_points; ++v)
      original.emplace(points[v], v);
  const auto origin = [&](std::size_t v) { return v < before_points ? v : original.at(points[v]); };
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& p = polygons[f];
    const Polygon& q = unoriented[f];
    bool same = p.size() == q.size();
    for (std::size_t k = 0; same && k < p.size(); ++k)
      same = origin(p[k]) == q[k];
    steps.faces_flipped += same ? 0 : 1;
  }

  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  std::vector<std::size_t> component_of(polygons.size(), 0);
  std::size_t components = 0;
  if (mesh.number_of_faces() == polygons.size()) {
    auto fcc = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
    components = PMP::connected_components(mesh, fcc);
    for (const auto f : mesh.faces())
      component_of[std::size_t(f)] = fcc[f];
  }
  std::vector<bool> closed(components, true), cut(components, false);
  for (const auto h : mesh.halfedges())
    if (mesh.is_border(h))
      closed[component_of[std::size_t(mesh.face(mesh.opposite(h)))]] = false;
  for (std::size_t f = 0; f < polygons.size(); ++f)
    for (const std::size_t v : polygons[f])
      if (v >= before_points && components > 0)
        cut[component_of[f]] = true;
  for (std::size_t c = 0; c < components; ++c) {
    steps.nonorientable_components += cut[c] ? 1 : 0;
    if (!closed[c] || cut[c])
      continue;
    // CGAL decides outwardness on triangles: fan the component's polygons.
    std::vector<Polygon> triangles;
    for (std::size_t f = 0; f < polygons.size(); ++f)
      if (component_of[f] == c)
        for (std::size_t k = 1; k + 1 < polygons[f].size(); ++k)
          triangles.push_back({polygons[f][0], polygons[f][k], polygons[f][k + 1]});
    Mesh tm;
    PMP::polygon_soup_to_polygon_mesh(points, triangles, tm);
    if (!CGAL::is_closed(tm) || PMP::is_outward_oriented(tm))
      continue;
    ++steps.components_turned_outward;
    for (std::size_t f = 0; f < polygons.size(); ++f)
      if (component_of[f] == c)
        std::reverse(polygons[f].begin(), polygons[f].end());
  }

  soup.points.resize(points.size());
  for (std::size_t v = 0; v < points.size(); ++v)
    soup.points[v] = {float(points[v].x()), float(points[v].y()), float(points[v].z())};
  if (coloured) {
    const std::vector<float> flat = carried_values(points, soup.colours[0].data(), 3, weld, colour_sums, origin);
    soup.colours.resize(points.size());
    for (std::size_t v = 0; v < points.size(); ++v)
      soup.colours[v] = {flat[v * 3], flat[v * 3 + 1], flat[v * 3 + 2]};
  }
  for (std::size_t c = 0; c < soup.channels.size(); ++c) {
    ChannelArray& a = soup.channels[c];
    a.values = carried_values(points, a.values.data(), std::size_t(a.components), weld, channel_sums[c], origin);
  }
  if (labelled) {
    std::vector<int> labels(points.size());
    for (std::size_t v = 0; v < points.size(); ++v) {
      if (!weld) {
        labels[v] = soup.labels[origin(v)];
        continue;
      }
      // The most frequent id among the merged vertices; ties go to the smallest.
      int best = -1, votes = 0;
      for (const auto& [id, n] : label_votes.at(points[v]))
        if (n > votes) {
          best = id;
          votes = n;
        }
      labels[v] = best;
    }
    soup.labels = std::move(labels);
  }
  soup.faces.assign(polygons.size(), {});
  for (std::size_t f = 0; f < polygons.size(); ++f)
    soup.faces[f].assign(polygons[f].begin(), polygons[f].end());
  soup.face_colours.clear();
  return steps;
}

} // namespace meshpaint
