// Base-mesh import: every format, polygons of any size, and what the
// checks and repairs do.

#include "core/errors.h"
#include "mesh/base_mesh.h"
#include "mesh/mesh_stats.h"
#include "mesh/openmesh_types.h"
#include "support/shapes.h"

#include <OpenMesh/Core/IO/MeshIO.hh> // for OpenMesh::IO::write_mesh

#include <gtest/gtest.h>

#include <algorithm>  // for std::rotate
#include <filesystem> // for std::filesystem
#include <fstream>    // for std::ofstream

namespace meshpaint {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir()
{
  const fs::path dir = fs::temp_directory_path() / ("meshpaint-import-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

//! Writes a base mesh through OpenMesh, the way a user's file would look.
std::string write_with_openmesh(const BaseMesh& mesh, const std::string& file)
{
  const PolyMesh om = to_openmesh(mesh);
  const std::string path = (temp_dir() / file).string();
  EXPECT_TRUE(OpenMesh::IO::write_mesh(om, path)) << path;
  return path;
}

std::string write_text(const std::string& file, const std::string& text)
{
  const std::string path = (temp_dir() / file).string();
  std::ofstream(path) << text;
  return path;
}

TEST(MeshImport, PolygonFormatsKeepEveryFace)
{
  for (const std::string ext : {".obj", ".off", ".ply"}) {
    const BaseMesh src = test::mixed_polygons();
    const BaseMesh back = load_mesh(write_with_openmesh(src, "mixed" + ext));
    EXPECT_EQ(back.vertex_count(), src.vertex_count()) << ext;
    ASSERT_EQ(back.face_count(), src.face_count()) << ext;
    EXPECT_EQ(back.face_sizes, src.face_sizes) << ext;
    EXPECT_FALSE(back.report.changed()) << ext;
  }
}

TEST(MeshImport, StlTriangles)
{
  const BaseMesh src = test::tetrahedron();
  const BaseMesh back = load_mesh(write_with_openmesh(src, "tet.stl"));
  EXPECT_EQ(back.vertex_count(), 4u); // STL repeats corners; the reader merges them
  EXPECT_EQ(back.face_count(), 4u);
}

TEST(MeshImport, StatsOfTestShapes)
{
  const MeshStats genus2 = compute_stats(test::genus_two());
  EXPECT_EQ(genus2.genus, 2);
  EXPECT_EQ(genus2.components, 1u);
  EXPECT_EQ(genus2.boundary_loops, 0u);
  const MeshStats grid = compute_stats(test::open_grid());
  EXPECT_EQ(grid.boundary_loops, 1u);
  EXPECT_EQ(grid.boundary_edges, 12u);
  EXPECT_EQ(grid.genus, 0);
  const MeshStats two = compute_stats(test::two_components());
  EXPECT_EQ(two.components, 2u);
  EXPECT_EQ(two.euler_characteristic, 4);
  const MeshStats apex = compute_stats(test::high_valence());
  EXPECT_EQ(apex.valences.rbegin()->first, 12);
  EXPECT_EQ(apex.faces_by_size.at(12), 1u);
}

TEST(MeshImport, RepairsAreCounted)
{
  // A bowtie: two triangles sharing only vertex 0.
  const BaseMesh bowtie = make_base_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}},
                                         {{0, 1, 2}, {0, 3, 4}}, "bowtie");
  EXPECT_EQ(bowtie.report.nonmanifold_vertices_split, 1u);
  EXPECT_EQ(bowtie.vertex_count(), 6u);

  // Three faces on one edge, a repeated vertex, an unused vertex.
  const BaseMesh fin = make_base_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {5, 5, 5}},
                                      {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {0, 2, 2}}, "fin");
  EXPECT_EQ(fin.report.degenerate_faces_dropped, 1u);
  EXPECT_EQ(fin.report.nonmanifold_faces_detached, 1u);
  EXPECT_GE(fin.report.isolated_vertices_removed, 1u);
  EXPECT_EQ(fin.face_count(), 3u);
  EXPECT_EQ(fin.report.lines().size(), 3u);
}

TEST(MeshImport, DuplicateFacesAreDroppedNotDetached)
{
  // A cube with one face repeated as is and one repeated reversed.
  const BaseMesh cube = test::cube();
  std::vector<std::vector<int>> faces;
  for (std::size_t f = 0; f < cube.face_count(); ++f)
    faces.emplace_back(cube.face_vertices.begin() + cube.face_offsets[f],
                       cube.face_vertices.begin() + cube.face_offsets[f + 1]);
  faces.push_back(faces[0]);
  faces.push_back({faces[1].rbegin(), faces[1].rend()});
  std::rotate(faces.back().begin(), faces.back().begin() + 1, faces.back().end());
  const BaseMesh back = make_base_mesh(cube.points, faces, "doubled");
  EXPECT_EQ(back.report.duplicate_faces_dropped, 2u);
  EXPECT_EQ(back.report.nonmanifold_faces_detached, 0u);
  EXPECT_EQ(back.face_count(), cube.face_count());
  EXPECT_EQ(back.vertex_count(), cube.vertex_count());
  EXPECT_EQ(compute_stats(back).components, 1u);
}

//! The import of `faces` on `points`, as a file's soup.
BaseMesh imported(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& faces)
{
  PolygonSoup soup;
  soup.points = points;
  soup.faces = faces;
  return import_mesh(soup, "soup", "soup: ");
}

TEST(MeshImport, OrientedManifoldSoupsKeepTheirFacesAndOthersAreOriented)
{
  // An oriented closed tetrahedron is taken as it is: no face turned, no vertex cut.
  const std::vector<Vec3> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::vector<int>> outward = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const BaseMesh clean = imported(tet, outward);
  EXPECT_EQ(clean.report.faces_flipped, 0u);
  EXPECT_EQ(clean.report.vertices_cut, 0u);
  EXPECT_EQ(clean.face_vertices, (std::vector<int>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));

  // One face turned against its neighbours: oriented again.
  std::vector<std::vector<int>> one_turned = outward;
  std::reverse(one_turned[3].begin(), one_turned[3].end());
  EXPECT_EQ(imported(tet, one_turned).report.faces_flipped, 1u);

  // Two closed tetrahedra touching at one vertex: every edge is manifold and
  // oriented, but the shared vertex has two closed fans, and is cut in two.
  std::vector<Vec3> pair = tet;
  for (const Vec3& p : {Vec3{0, 0, -1}, Vec3{-1, 0, 0}, Vec3{0, -1, 0}})
    pair.push_back(p);
  std::vector<std::vector<int>> faces = outward;
  for (const std::vector<int>& f : outward) { // the mirror image through the origin, still outward
    std::vector<int> g;
    for (const int v : f)
      g.push_back(v == 0 ? 0 : v + 3);
    std::reverse(g.begin(), g.end());
    faces.push_back(g);
  }
  const BaseMesh touching = imported(pair, faces);
  EXPECT_EQ(touching.vertex_count(), 8u);
  EXPECT_EQ(touching.report.vertices_cut, 1u); // by CGAL's orienter, before the OpenMesh build
  EXPECT_EQ(touching.report.nonmanifold_vertices_split, 0u);
  EXPECT_EQ(compute_stats(touching).components, 2u);
}

TEST(MeshImport, ClosedComponentsFacingInwardAreTurnedAndNoOthers)
{
  // Three components: a tetrahedron facing inward, one facing outward, an
  // open sheet facing down. Oriented manifolds all, so the linear path
  // judges them; one face of the sheet reversed sends the soup through
  // CGAL's orienter instead, with the same verdict on the tetrahedra.
  const std::vector<Vec3> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::vector<int>> outward = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  const auto add = [&](const std::vector<Vec3>& ps, std::vector<std::vector<int>> fs, Vec3 shift, bool reverse) {
    const int base = int(points.size());
    for (const Vec3& p : ps)
      points.push_back({p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]});
    for (std::vector<int>& f : fs) {
      for (int& v : f)
        v += base;
      if (reverse)
        std::reverse(f.begin(), f.end());
      faces.push_back(f);
    }
  };
  add(tet, outward, {0, 0, 0}, true);
  add(tet, outward, {3, 0, 0}, false);
  add({{0, 0, 5}, {1, 0, 5}, {1, 1, 5}, {0, 1, 5}}, {{0, 2, 1}, {0, 3, 2}}, {0, 0, 0}, false);
  const BaseMesh linear = imported(points, faces);
  EXPECT_EQ(linear.report.components_turned_outward, 1u);
  EXPECT_EQ(linear.report.faces_flipped, 0u);
  for (int f = 0; f < 4; ++f) // the inward tetrahedron, turned back: the outward faces
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(linear.face_vertices[std::size_t(3 * f + k)], outward[std::size_t(f)][std::size_t(k)]);
  for (int f = 4; f < 10; ++f) // the others as they were
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(linear.face_vertices[std::size_t(3 * f + k)], faces[std::size_t(f)][std::size_t(k)]);

  std::vector<std::vector<int>> one_turned = faces;
  std::reverse(one_turned.back().begin(), one_turned.back().end());
  const BaseMesh oriented = imported(points, one_turned);
  EXPECT_EQ(oriented.report.components_turned_outward, 1u);
  EXPECT_EQ(oriented.report.faces_flipped, 1u);
}

TEST(MeshImport, ClosedSurfacesWeldOnlyPointsAtOnePosition)
{
  // Two closed tetrahedra, each with its own vertices, one pair of them at
  // one position: joined (then cut again, two closed fans). Every fan is
  // closed, so no other pair could join, however close.
  const std::vector<Vec3> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::vector<int>> outward = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::vector<Vec3> points = tet;
  for (const Vec3& p : tet)
    points.push_back({-p[0], -p[1], -p[2]}); // the mirror image, vertex 4 at -0
  std::vector<std::vector<int>> faces = outward;
  for (const std::vector<int>& f : outward)
    faces.push_back({f[2] + 4, f[1] + 4, f[0] + 4});
  EXPECT_EQ(imported(points, faces).report.vertices_welded, 1u);
  for (Vec3& p : points)
    if (&p >= &points[4])
      p[0] += 1e-7f; // within the weld tolerance, but no border
  EXPECT_EQ(imported(points, faces).report.vertices_welded, 0u);
}

TEST(MeshImport, BadInputNamesTheProblem)
{
  EXPECT_THROW(load_mesh("/nonexistent/mesh.off"), IOError);
  EXPECT_THROW(load_mesh(write_text("x.abc", "v 0 0 0\n")), InputError);
  try {
    load_mesh(write_text("gap.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
    FAIL() << "accepted a face naming a missing vertex";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 names vertex 7"), std::string::npos) << e.what();
  }
  try {
    make_base_mesh({{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}}, {{0, 1, 2}}, "nan");
    FAIL() << "accepted a NaN coordinate";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 2 has a non-finite coordinate"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make_base_mesh({{0, 0, 0}}, {}, "empty"), InputError);
}

} // namespace
} // namespace meshpaint
