// The first reduction of large scans: passes of independent quadric edge
// collapses keep the surface a manifold of the same topology, near the
// input, with its borders where they were.
#include "mesh/decimate.h"
#include "mesh/quadric_passes.h"
#include "support/shapes.h"

#include <CGAL/boost/graph/helpers.h> // for is_valid_polygon_mesh, is_closed

#include <gtest/gtest.h>

#include <cmath> // for std::sqrt, std::abs

using namespace meshpaint;
using namespace meshpaint::test;

namespace {

long euler_characteristic(const CgalMesh& m)
{
  return long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
}

std::size_t border_halfedges(const CgalMesh& m)
{
  std::size_t n = 0;
  for (const CgalMesh::Halfedge_index h : m.halfedges())
    n += m.is_border(h);
  return n;
}

} // namespace

TEST(QuadricPasses, AClosedSphereStaysAClosedSphereNearItsSurface)
{
  CgalMesh mesh = cgal_triangles(noisy_sphere(40, 0.002f)); // 19,200 triangles
  ASSERT_EQ(mesh.number_of_faces(), 19200u);
  const QuadricPasses passes = reduce_in_passes(mesh, 2000);
  EXPECT_GT(passes.passes, 1);
  EXPECT_EQ(passes.faces, mesh.number_of_faces());
  EXPECT_LE(mesh.number_of_faces(), 2000u);
  EXPECT_GT(mesh.number_of_faces(), 1900u); // one collapse removes two faces; the last pass stops at the target
  mesh.collect_garbage();
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(euler_characteristic(mesh), 2);
  for (const CgalMesh::Vertex_index v : mesh.vertices()) {
    const double r = std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length());
    EXPECT_NEAR(r, 1.0, 0.02);
  }
}

TEST(QuadricPasses, ABorderStaysWhereItWas)
{
  // A 60 x 60 grid of quads, 7,200 triangles, with one border around it.
  CgalMesh mesh = cgal_triangles(flat_grid(60));
  const QuadricPasses passes = reduce_in_passes(mesh, 400);
  EXPECT_LE(passes.faces, 400u);
  mesh.collect_garbage();
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_EQ(euler_characteristic(mesh), 1);
  EXPECT_GT(border_halfedges(mesh), 0u);
  double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
  for (const CgalMesh::Vertex_index v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    EXPECT_EQ(p.z(), 0.0); // the plane's quadric holds every vertex in it
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
    if (mesh.is_border(v)) { // on one of the square's four sides
      const double side = std::min({std::abs(p.x()), std::abs(p.x() - 60), std::abs(p.y()), std::abs(p.y() - 60)});
      EXPECT_LT(side, 1e-9) << p;
    }
  }
  EXPECT_EQ(lo[0], 0.0);
  EXPECT_EQ(lo[1], 0.0);
  EXPECT_EQ(hi[0], 60.0);
  EXPECT_EQ(hi[1], 60.0);
}

TEST(QuadricPasses, KeepsTheGenus)
{
  CgalMesh mesh = cgal_triangles(genus_two());
  const long chi = euler_characteristic(mesh);
  reduce_in_passes(mesh, 4); // far below what a genus-two surface allows
  mesh.collect_garbage();
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(mesh));
  EXPECT_TRUE(CGAL::is_closed(mesh));
  EXPECT_EQ(euler_characteristic(mesh), chi);
}

TEST(Decimate, LargeScansGoThroughThePassesFirst)
{
  // Just over the threshold: 6 x 290 x 290 quads, 1,009,200 triangles.
  const BaseMesh scan = noisy_sphere(290, 0.0005f);
  ASSERT_GT(2 * scan.face_count(), kQuadricPassesAbove);
  const Decimation d = decimate(scan, 2500);
  EXPECT_GT(d.passes.passes, 0);
  EXPECT_LE(d.passes.faces, kQuadricPassesLeave * 2500);
  EXPECT_LE(d.base.face_count(), 2500u);
  const Decimation small = decimate(noisy_sphere(40, 0.002f), 2500);
  EXPECT_EQ(small.passes.passes, 0);
}
