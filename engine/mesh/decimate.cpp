#include "mesh/decimate.h"

#include <CGAL/Simple_cartesian.h> // for CGAL::Simple_cartesian
#include <CGAL/Surface_mesh.h>     // for CGAL::Surface_mesh
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_filter.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h> // for edge_collapse

#include <algorithm> // for std::min, std::max
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMS = CGAL::Surface_mesh_simplification;

//! Stops the collapses once the mesh has at most `budget` faces.
struct FaceBudget
{
  const CgalMesh* mesh;
  std::size_t budget;
  template <typename Cost, typename Profile>
  bool operator()(const Cost&, const Profile&, std::size_t, std::size_t) const
  {
    return mesh->number_of_faces() <= budget;
  }
};

//! One stage: Garland-Heckbert plane quadrics order and place the
//! collapses until the budget or until none is allowed; stage 1 refuses a
//! collapse that turns any face of its star by more than 90 degrees.
void decimate_stage(CgalMesh& mesh, std::size_t target_faces, int stage)
{
  SMS::GarlandHeckbert_plane_policies<CgalMesh, Kernel> policies(mesh);
  const auto params = CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement());
  if (stage == 1)
    SMS::edge_collapse(mesh, FaceBudget{&mesh, target_faces}, params.filter(SMS::Bounded_normal_change_filter<>()));
  else
    SMS::edge_collapse(mesh, FaceBudget{&mesh, target_faces}, params);
}

} // namespace

std::size_t default_base_faces(std::size_t faces) { return std::min<std::size_t>(20000, std::max<std::size_t>(2500, faces / 50)); }

Decimation decimate(const BaseMesh& mesh, std::size_t target_faces)
{
  CgalMesh cm;
  cm.reserve(CgalMesh::size_type(mesh.vertex_count()), CgalMesh::size_type(3 * mesh.face_count()),
             CgalMesh::size_type(2 * mesh.face_count()));
  for (const Vec3& p : mesh.points)
    cm.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const int* v = &mesh.face_vertices[std::size_t(mesh.face_offsets[f])];
    for (int k = 1; k + 1 < mesh.face_sizes[f]; ++k)
      cm.add_face(CgalMesh::Vertex_index(CgalMesh::size_type(v[0])), CgalMesh::Vertex_index(CgalMesh::size_type(v[k])),
                  CgalMesh::Vertex_index(CgalMesh::size_type(v[k + 1])));
  }

  Decimation result;
  result.budget = target_faces;
  for (int stage = 1; stage <= 2 && (stage == 1 || cm.number_of_faces() > target_faces); ++stage) {
    decimate_stage(cm, target_faces, stage);
    result.stage_faces[stage - 1] = cm.number_of_faces();
    result.stages = stage;
  }
  cm.collect_garbage();

  std::vector<Vec3> points;
  points.reserve(cm.number_of_vertices());
  for (const CgalMesh::Vertex_index v : cm.vertices()) {
    const Kernel::Point_3& p = cm.point(v);
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
