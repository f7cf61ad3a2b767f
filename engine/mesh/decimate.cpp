#include "mesh/decimate.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>       // for TriMesh_ArrayKernelT
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>           // for DecimaterT
#include <OpenMesh/Tools/Decimater/ModNormalDeviationT.hh>  // for ModNormalDeviationT
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>   // for ModNormalFlippingT
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>          // for ModQuadricT

#include <algorithm> // for std::min, std::max
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

//! Largest normal change, degrees, that the stages allow.
constexpr double kMaxNormalDegrees = 60.0;

//! One stage: collapses in quadric order until `target_faces` or until no
//! collapse is allowed; stage 1 bounds normal cones, later ones normal flips.
void decimate_stage(TriMesh& tm, std::size_t target_faces, int stage)
{
  for (const auto vh : tm.vertices())
    tm.status(vh).set_locked(stage < 3 && tm.is_boundary(vh));
  OpenMesh::Decimater::DecimaterT<TriMesh> decimater(tm);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  decimater.add(quadric);
  decimater.module(quadric).unset_max_err();
  OpenMesh::Decimater::ModNormalDeviationT<TriMesh>::Handle deviation;
  OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle flipping;
  if (stage == 1) {
    decimater.add(deviation);
    decimater.module(deviation).set_normal_deviation(kMaxNormalDegrees);
  } else {
    decimater.add(flipping);
    decimater.module(flipping).set_max_normal_deviation(kMaxNormalDegrees);
  }
  decimater.initialize();
  decimater.decimate_to_faces(0, target_faces);
  tm.garbage_collection();
}

} // namespace

std::size_t default_base_faces(std::size_t faces) { return std::min<std::size_t>(20000, std::max<std::size_t>(2500, faces / 50)); }

Decimation decimate(const BaseMesh& mesh, std::size_t target_faces)
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

  Decimation result;
  result.budget = target_faces;
  for (int stage = 1; stage <= 3 && (stage == 1 || tm.n_faces() > target_faces); ++stage) {
    decimate_stage(tm, target_faces, stage);
    result.stage_faces[stage - 1] = tm.n_faces();
    result.stages = stage;
  }

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
  result.base = make_base_mesh(std::move(points), faces, mesh.name);
  return result;
}

} // namespace meshpaint
