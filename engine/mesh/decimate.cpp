#include "mesh/decimate.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>  // for TriMesh_ArrayKernelT
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>        // for DecimaterT
#include <OpenMesh/Tools/Decimater/ModNormalDeviationT.hh> // for ModNormalDeviationT
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>       // for ModQuadricT

#include <algorithm> // for std::min, std::max
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

} // namespace

std::size_t default_base_faces(std::size_t faces) { return std::min<std::size_t>(20000, std::max<std::size_t>(200, faces / 50)); }

BaseMesh decimate(const BaseMesh& mesh, std::size_t target_faces)
{
  TriMesh tm;
  tm.reserve(mesh.vertex_count(), 3 * mesh.face_count(), 2 * mesh.face_count());
  for (const Vec3& p : mesh.points)
    tm.add_vertex(TriMesh::Point(p[0], p[1], p[2]));
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const int* v = &mesh.face_vertices[std::size_t(mesh.face_offsets[f])];
    for (int k = 1; k + 1 < mesh.face_sizes[f]; ++k)
      tm.add_face(TriMesh::VertexHandle(v[0]), TriMesh::VertexHandle(v[k]), TriMesh::VertexHandle(v[k + 1]));
  }
  tm.request_vertex_status();
  tm.request_edge_status();
  tm.request_face_status();
  tm.request_face_normals();
  tm.update_face_normals();
  for (const auto vh : tm.vertices())
    if (tm.is_boundary(vh))
      tm.status(vh).set_locked(true);

  OpenMesh::Decimater::DecimaterT<TriMesh> decimater(tm);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalDeviationT<TriMesh>::Handle deviation;
  decimater.add(quadric);
  decimater.add(deviation);
  decimater.module(quadric).unset_max_err();
  decimater.module(deviation).set_normal_deviation(60.0);
  decimater.initialize();
  decimater.decimate_to_faces(0, target_faces);
  tm.garbage_collection();

  std::vector<Vec3> points;
  points.reserve(tm.n_vertices());
  for (const auto vh : tm.vertices()) {
    const auto& p = tm.point(vh);
    points.push_back({p[0], p[1], p[2]});
  }
  std::vector<std::vector<int>> faces;
  faces.reserve(tm.n_faces());
  for (const auto fh : tm.faces()) {
    std::vector<int> f;
    for (const auto vh : tm.fv_range(fh))
      f.push_back(vh.idx());
    faces.push_back(f);
  }
  return make_base_mesh(std::move(points), faces, mesh.name);
}

} // namespace meshpaint
