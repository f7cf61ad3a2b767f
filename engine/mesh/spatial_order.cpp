#include "mesh/spatial_order.h"

#include <algorithm> // for std::stable_sort, std::sort, std::min, std::max
#include <cstdint>   // for std::uint32_t, std::uint64_t
#include <numeric>   // for std::iota
#include <utility>   // for std::pair

namespace meshpaint {
namespace {

//! Spreads the low 21 bits of x to every third bit.
std::uint64_t spread3(std::uint64_t x)
{
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

//! Morton codes over a box: 21 bits per axis.
struct MortonBox
{
  Vec3 lo, hi;

  explicit MortonBox(const std::vector<Vec3>& points) : lo(points.front()), hi(points.front())
  {
    for (const Vec3& p : points)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
  }

  std::uint64_t code(const double c[3]) const
  {
    std::uint64_t q[3];
    for (int a = 0; a < 3; ++a) {
      const double extent = double(hi[a]) - double(lo[a]);
      const double u = extent > 0 ? (c[a] - lo[a]) / extent : 0.0;
      q[a] = std::uint64_t(std::min(std::max(u, 0.0), 1.0) * double((1u << 21) - 1));
    }
    return spread3(q[0]) | spread3(q[1]) << 1 | spread3(q[2]) << 2;
  }
};

} // namespace

std::vector<std::size_t> morton_order(const std::vector<Vec3>& points)
{
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  if (points.empty())
    return order;
  const MortonBox box(points);
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double c[3] = {points[k][0], points[k][1], points[k][2]};
    keyed[k] = {box.code(c), k};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < points.size(); ++k)
    order[k] = keyed[k].second;
  return order;
}

BaseMesh spatially_ordered(const BaseMesh& mesh, std::vector<int>* face_order)
{
  const std::size_t nf = mesh.face_count();
  const MortonBox box(mesh.points);
  std::vector<std::uint64_t> code(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    double c[3] = {0, 0, 0};
    const int n = mesh.face_sizes[f];
    for (int k = 0; k < n; ++k)
      for (int a = 0; a < 3; ++a)
        c[a] += mesh.points[mesh.face_vertices[mesh.face_offsets[f] + k]][a];
    for (int a = 0; a < 3; ++a)
      c[a] /= n;
    code[f] = box.code(c);
  }
  std::vector<int> order(nf);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return code[a] < code[b]; });

  BaseMesh out;
  out.name = mesh.name;
  out.report = mesh.report;
  out.channels = without_values(mesh.channels);
  out.label_classes = mesh.label_classes;
  std::vector<int> renumber(mesh.vertex_count(), -1);
  out.face_offsets.push_back(0);
  for (const int f : order) {
    for (int k = 0; k < mesh.face_sizes[f]; ++k) {
      int& v = renumber[mesh.face_vertices[mesh.face_offsets[f] + k]];
      if (v < 0) {
        v = int(out.points.size());
        out.points.push_back(mesh.points[mesh.face_vertices[mesh.face_offsets[f] + k]]);
        if (!mesh.colours.empty())
          out.colours.push_back(mesh.colours[mesh.face_vertices[mesh.face_offsets[f] + k]]);
        if (!mesh.labels.empty())
          out.labels.push_back(mesh.labels[mesh.face_vertices[mesh.face_offsets[f] + k]]);
        append_vertex(out.channels, mesh.channels, std::size_t(mesh.face_vertices[mesh.face_offsets[f] + k]));
      }
      out.face_vertices.push_back(v);
    }
    out.face_sizes.push_back(mesh.face_sizes[f]);
    out.face_offsets.push_back(int(out.face_vertices.size()));
  }
  if (face_order)
    *face_order = order;
  return out;
}

} // namespace meshpaint
