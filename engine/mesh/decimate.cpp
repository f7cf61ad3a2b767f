#include "mesh/decimate.h"

#include "mesh/edge_collapse.h"
#include "mesh/quadric_passes.h"
#include "mesh/spatial_order.h"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_filter.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h> // for edge_collapse

#include <algorithm> // for std::min, std::max
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

namespace SMS = CGAL::Surface_mesh_simplification;

//! One stage: Garland-Heckbert plane quadrics order and place the
//! collapses until the budget or until none is allowed; stage 1 refuses a
//! collapse that turns any face of its star by more than 90 degrees.
void decimate_stage(CgalMesh& mesh, std::size_t target_faces, int stage)
{
  SMS::GarlandHeckbert_plane_policies<CgalMesh, CgalKernel> policies(mesh);
  const auto params = CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement());
  if (stage == 1)
    SMS::edge_collapse(mesh, FaceBudget{&mesh, target_faces}, params.filter(SMS::Bounded_normal_change_filter<>()));
  else
    SMS::edge_collapse(mesh, FaceBudget{&mesh, target_faces}, params);
}

} // namespace

std::size_t default_base_faces(std::size_t faces) { return std::min<std::size_t>(20000, std::max<std::size_t>(2500, faces / 50)); }

CgalMesh cgal_triangles(const BaseMesh& mesh)
{
  CgalMesh cm;
  cm.reserve(CgalMesh::size_type(mesh.vertex_count()), CgalMesh::size_type(3 * mesh.face_count()),
             CgalMesh::size_type(2 * mesh.face_count()));
  for (const Vec3& p : mesh.points)
    cm.add_vertex(CgalKernel::Point_3(p[0], p[1], p[2]));
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const int* v = &mesh.face_vertices[std::size_t(mesh.face_offsets[f])];
    for (int k = 1; k + 1 < mesh.face_sizes[f]; ++k)
      cm.add_face(CgalMesh::Vertex_index(CgalMesh::size_type(v[0])), CgalMesh::Vertex_index(CgalMesh::size_type(v[k])),
                  CgalMesh::Vertex_index(CgalMesh::size_type(v[k + 1])));
  }
  return cm;
}

Decimation decimate(const BaseMesh& mesh, std::size_t target_faces)
{
  const std::size_t triangles = mesh.triangle_count();
  const bool passes = triangles > kQuadricPassesAbove && triangles > kQuadricPassesLeave * target_faces;
  // The passes read every edge's two ends (their quadrics and points) on
  // each pass: in file order these jump through hundreds of megabytes, in
  // Morton order they mostly hit the cache.
  CgalMesh cm = passes ? cgal_triangles(spatially_ordered(mesh)) : cgal_triangles(mesh);
  Decimation result;
  result.budget = target_faces;
  if (passes) {
    result.passes = reduce_in_passes(cm, kQuadricPassesLeave * target_faces);
    cm.collect_garbage(); // the ordered collapse indexes vertices densely
  }
  for (int stage = 1; stage <= 2 && (stage == 1 || cm.number_of_faces() > target_faces); ++stage) {
    decimate_stage(cm, target_faces, stage);
    result.stage_faces[stage - 1] = cm.number_of_faces();
    result.stages = stage;
  }
  cm.collect_garbage();

  std::vector<Vec3> points;
  points.reserve(cm.number_of_vertices());
  for (const CgalMesh::Vertex_index v : cm.vertices()) {
    const CgalKernel::Point_3& p = cm.point(v);
    points.push_back({float(p.x()), float(p.y()), float(p.z())});
  }
  std::vector<std::vector<int>> faces;
  faces.reserve(cm.number_of_faces());
  for (const CgalMesh::Face_index f : cm.faces()) {
    std::vector<int> face;
    for (const CgalMesh::Vertex_index v : vertices_around_face(cm.halfedge(f), cm))
      face.push_back(int(v));
    faces.push_back(face);
  }
  result.base = make_base_mesh(std::move(points), faces, mesh.name);
  return result;
}

} // namespace meshpaint
