// The peers: vtkQuadricDecimation reaches a face count through its target
// reduction; CGAL's edge collapse stops where our predicate says the
// budget is met. The distances come from the same locator-based query that
// `meshpaint fit` measures with.

#include "decimation_peers.h"

#include "project/aabb_surface_query.h" // for meshpaint::aabb_surface_queries

#include "core/timer.h"
#include "mesh/decimate.h"
#include "mesh/edge_collapse.h"

#include <vtkCellArray.h>          // for vtkCellArray
#include <vtkIdList.h>             // for vtkIdList
#include <vtkNew.h>                // for vtkNew
#include <vtkPoints.h>             // for vtkPoints
#include <vtkPolyData.h>           // for vtkPolyData
#include <vtkQuadricDecimation.h>  // for vtkQuadricDecimation

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h> // for edge_collapse

#include <algorithm> // for std::sort
#include <array>     // for std::array
#include <functional> // for std::function

namespace meshpaint::cli {
namespace {

namespace SMS = CGAL::Surface_mesh_simplification;

using Triangles = std::vector<std::array<int, 3>>;

struct Surface
{
  std::vector<Vec3> points;
  Triangles triangles;
};

//! Runs `decimate` `repeats` times; the median seconds and the last result.
double median_seconds(int repeats, const std::function<void()>& decimate)
{
  std::vector<double> seconds;
  for (int r = 0; r < repeats; ++r) {
    const Timer t;
    decimate();
    seconds.push_back(t.ms() / 1000);
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

DecimationPeer measured(const std::string& method, double seconds, const Surface& s, const BaseMesh& scan)
{
  DecimationPeer peer;
  peer.method = method;
  peer.faces = s.triangles.size();
  peer.seconds = seconds;
  peer.scan_to_mesh = surface_distance(*aabb_surface_queries()(s.points, s.triangles), scan.points);
  return peer;
}

vtkSmartPointer<vtkPolyData> polydata(const std::vector<Vec3>& points, const Triangles& triangles)
{
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  for (const Vec3& v : points)
    p->InsertNextPoint(v[0], v[1], v[2]);
  vtkNew<vtkCellArray> polys;
  for (const auto& t : triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(p);
  out->SetPolys(polys);
  return out;
}

Surface surface_of(vtkPolyData* mesh)
{
  Surface s;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double x[3];
    mesh->GetPoint(i, x);
    s.points.push_back({float(x[0]), float(x[1]), float(x[2])});
  }
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c) {
    polys->GetCellAtId(c, ids);
    if (ids->GetNumberOfIds() == 3)
      s.triangles.push_back({int(ids->GetId(0)), int(ids->GetId(1)), int(ids->GetId(2))});
  }
  return s;
}

DecimationPeer vtk_quadric(const BaseMesh& scan, const Triangles& triangles, std::size_t budget, bool preserve_volume,
                           int repeats)
{
  const vtkSmartPointer<vtkPolyData> input = polydata(scan.points, triangles);
  vtkSmartPointer<vtkPolyData> output;
  const double seconds = median_seconds(repeats, [&] {
    vtkNew<vtkQuadricDecimation> decimation;
    decimation->SetInputData(input);
    decimation->SetTargetReduction(1.0 - double(budget) / double(triangles.size()));
    decimation->SetVolumePreservation(preserve_volume);
    decimation->Update();
    output = decimation->GetOutput();
  });
  return measured(preserve_volume ? "vtkQuadricDecimation, volume preservation" : "vtkQuadricDecimation", seconds,
                  surface_of(output), scan);
}

DecimationPeer cgal_garland_heckbert(const BaseMesh& scan, std::size_t budget, int repeats)
{
  const CgalMesh input = cgal_triangles(scan); // the polygons fanned as `triangles` are
  CgalMesh mesh;
  const double seconds = median_seconds(repeats, [&] {
    mesh = input;
    SMS::GarlandHeckbert_plane_policies<CgalMesh, CgalKernel> policies(mesh);
    SMS::edge_collapse(mesh, FaceBudget{&mesh, budget},
                       CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
  });
  mesh.collect_garbage();
  Surface s;
  for (CgalMesh::Vertex_index v : mesh.vertices()) {
    const CgalKernel::Point_3& p = mesh.point(v);
    s.points.push_back({float(p.x()), float(p.y()), float(p.z())});
  }
  for (CgalMesh::Face_index f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (CgalMesh::Vertex_index v : vertices_around_face(mesh.halfedge(f), mesh))
      if (k < 3)
        t[std::size_t(k++)] = int(v);
    s.triangles.push_back(t);
  }
  return measured("CGAL edge collapse, Garland-Heckbert planes", seconds, s, scan);
}

} // namespace

std::vector<DecimationPeer> decimation_peers(const BaseMesh& scan, std::size_t budget, int repeats)
{
  const Triangles triangles = triangles_of(scan);
  std::vector<DecimationPeer> peers;
  Decimation ours;
  const double seconds = median_seconds(repeats, [&] { ours = decimate(scan, budget); });
  peers.push_back(measured("meshpaint decimate()", seconds, {ours.base.points, triangles_of(ours.base)}, scan));
  peers.push_back(vtk_quadric(scan, triangles, budget, false, repeats));
  peers.push_back(vtk_quadric(scan, triangles, budget, true, repeats));
  peers.push_back(cgal_garland_heckbert(scan, budget, repeats));
  return peers;
}

} // namespace meshpaint::cli
