#include "ScanTransfer.h"

#include "PolyDataFiles.h"     // for meshpaint::read_polydata_file, read_checked
#include "SurfaceConversion.h" // for meshpaint::to_polydata, colour_byte

#include "core/errors.h"     // for meshpaint::IOError, InputError
#include "core/parallel_for.h" // for meshpaint::parallel_for
#include "project/aabb_surface_query.h" // for meshpaint::aabb_surface_queries
#include "core/format.h"     // for meshpaint::lower_extension
#include "mesh/base_mesh.h"  // for meshpaint::load_mesh
#include "mesh/property_ply.h" // for meshpaint::write_property_ply
#include "mesh/spatial_order.h" // for meshpaint::morton_order

#include <vtkAlgorithm.h>         // for vtkAlgorithm
#include <vtkCellData.h>          // for vtkCellData
#include <vtkCellArray.h>         // for vtkCellArray
#include <vtkFloatArray.h>        // for vtkFloatArray
#include <vtkGenericCell.h>       // for vtkGenericCell
#include <vtkIntArray.h>          // for vtkIntArray
#include <vtkOBJReader.h>         // for vtkOBJReader
#include <vtkPLYReader.h>         // for vtkPLYReader
#include <vtkPointData.h>         // for vtkPointData
#include <vtkPoints.h>            // for vtkPoints

#include <algorithm>  // for std::find, std::max_element
#include <array>      // for std::array
#include <memory>     // for std::unique_ptr
#include <vector>     // for std::vector
#include <cmath>      // for std::sqrt, std::isfinite
#include <filesystem> // for std::filesystem::is_regular_file

namespace meshpaint {
namespace {

//! Points and polygons in the file's own order.
vtkSmartPointer<vtkPolyData> polygons_of(const PolygonSoup& soup)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vtkIdType(soup.points.size()));
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    points->SetPoint(vtkIdType(v), soup.points[v].data());
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& face : soup.faces) {
    cells->InsertNextCell(vtkIdType(face.size()));
    for (const int v : face)
      cells->InsertCellPoint(v);
  }
  poly->SetPoints(points);
  poly->SetPolys(cells);
  return poly;
}

//! The quads split into two triangles each, (0, 1, 2) and (0, 2, 3):
//! closest points on them are exact, and triangle t lies in quad t / 2.
vtkSmartPointer<vtkPolyData> triangles_of(const WeldedSurface& s)
{
  WeldedSurface plain;
  plain.points = s.points;
  vtkSmartPointer<vtkPolyData> poly = to_polydata(plain);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->AllocateExact(vtkIdType(2 * s.quads.size()), vtkIdType(6 * s.quads.size()));
  for (const auto& q : s.quads) {
    const vtkIdType a[3] = {q[0], q[1], q[2]}, b[3] = {q[0], q[2], q[3]};
    cells->InsertNextCell(3, a);
    cells->InsertNextCell(3, b);
  }
  poly->SetPolys(cells);
  return poly;
}

vtkSmartPointer<vtkFloatArray> float_array(const char* name, int components, vtkIdType tuples)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

//! One PLY property per component of every array of `data`.
std::vector<PlyProperty> component_properties(vtkDataSetAttributes* data)
{
  std::vector<PlyProperty> out;
  for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = data->GetArray(a);
    if (!array)
      continue; // string and other non-numeric arrays have no PLY type
    std::string name = array->GetName() ? array->GetName() : "array" + std::to_string(a);
    for (char& c : name)
      if (c == ' ')
        c = '_';
    const int k = array->GetNumberOfComponents();
    const bool colour = name == "diffuse" || name == "specular";
    for (int c = 0; c < k; ++c) {
      PlyProperty p;
      p.name = k == 1 ? name
               : k == 3 ? name + "_" + (colour ? "rgb" : "xyz")[c]
                        : name + "_" + std::to_string(c);
      p.integer = array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE;
      p.values.resize(std::size_t(array->GetNumberOfTuples()));
      for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
        p.values[std::size_t(t)] = array->GetComponent(t, c);
      out.push_back(std::move(p));
    }
  }
  return out;
}

//! `rgb` (3 components, 0..1) as the uchar properties red, green and blue.
std::vector<PlyProperty> colour_properties(vtkDataArray* rgb)
{
  std::vector<PlyProperty> out(3);
  const char* names[3] = {"red", "green", "blue"};
  for (int c = 0; c < 3; ++c) {
    out[std::size_t(c)].name = names[c];
    out[std::size_t(c)].byte = true;
    out[std::size_t(c)].values.resize(std::size_t(rgb->GetNumberOfTuples()));
    for (vtkIdType t = 0; t < rgb->GetNumberOfTuples(); ++t)
      out[std::size_t(c)].values[std::size_t(t)] = colour_byte(float(rgb->GetComponent(t, c)));
  }
  return out;
}

} // namespace

void write_scan_ply(vtkPolyData* scan, const std::string& path)
{
  const vtkIdType others = scan->GetNumberOfVerts() + scan->GetNumberOfLines() + scan->GetNumberOfStrips();
  if (others > 0)
    throw InputError("cannot write '" + path + "': the scan has " + std::to_string(others) +
                     " vertex, line or strip cells, which PLY holds only as polygons; write .vtp instead");
  std::vector<Vec3> points(std::size_t(scan->GetNumberOfPoints()));
  for (vtkIdType v = 0; v < scan->GetNumberOfPoints(); ++v) {
    double x[3];
    scan->GetPoint(v, x);
    points[std::size_t(v)] = {float(x[0]), float(x[1]), float(x[2])};
  }
  // The polygons as offsets and corners (cell f is polygon f: there are no
  // other cells).
  std::vector<int> offsets{0}, corners;
  offsets.reserve(std::size_t(scan->GetNumberOfPolys()) + 1);
  vtkCellArray* polys = scan->GetPolys();
  corners.reserve(std::size_t(polys->GetNumberOfConnectivityIds()));
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);) {
    for (vtkIdType k = 0; k < count; ++k)
      corners.push_back(int(ids[k]));
    offsets.push_back(int(corners.size()));
  }
  std::vector<PlyProperty> vertex; // the colours first: what MeshLab and CloudCompare show
  if (vtkDataArray* diffuse = scan->GetPointData()->GetArray("diffuse"); diffuse && diffuse->GetNumberOfComponents() == 3)
    vertex = colour_properties(diffuse);
  for (PlyProperty& p : component_properties(scan->GetPointData()))
    vertex.push_back(std::move(p));
  write_property_ply(points, offsets, corners, vertex, component_properties(scan->GetCellData()), path);
}

const std::vector<std::string>& scan_extensions()
{
  static const std::vector<std::string> exts = {".vtp", ".vtk", ".ply", ".obj", ".stl", ".off"};
  return exts;
}

vtkSmartPointer<vtkPolyData> read_scan(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw IOError("cannot open '" + path + "': no such file");
  const std::string ext = lower_extension(path);
  const auto& exts = scan_extensions();
  if (std::find(exts.begin(), exts.end(), ext) == exts.end())
    throw InputError("cannot read scan '" + path + "': unknown format '" + ext + "' (.vtp .vtk .ply .obj .stl .off)");
  // The one checked path every mesh file takes first: nothing reaches a VTK
  // reader that the census and the strict readers have not accepted.
  if (!is_polydata_path(path)) {
    const PolygonSoup soup = read_mesh_file(path);
    // STL carries no point arrays: the checked reading is the scan (VTK's
    // reader would also stumble on a byte-order mark).
    if (ext == ".off" || ext == ".stl")
      return polygons_of(soup);
  } else {
    return read_polydata_file(path);
  }
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".ply") {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  return read_checked(reader, path);
}

TransferReport transfer_to_scan(const PaintedSurface& painted, const WeldedSurface& reference, vtkPolyData* scan,
                                bool geometry)
{
  if (painted.surface.points.size() != reference.points.size() || painted.surface.quads != reference.quads)
    throw InputError("the painted and the reference surface differ in their vertices or quads");
  vtkSmartPointer<vtkPolyData> triangles = triangles_of(reference);
  const vtkIdType n = scan->GetNumberOfPoints();
  // The closest triangle of every scan vertex, on every core (the engine's
  // AABB tree; VTK 9.1's static locator clears a bit per triangle on every
  // query, minutes for a scan of millions of vertices).
  std::vector<Vec3> at(static_cast<std::size_t>(n));
  for (vtkIdType v = 0; v < n; ++v) {
    double x[3];
    scan->GetPoint(v, x);
    at[std::size_t(v)] = {float(x[0]), float(x[1]), float(x[2])};
  }
  std::vector<std::array<int, 3>> corners;
  corners.reserve(2 * reference.quads.size());
  for (const auto& q : reference.quads) { // in triangles_of()'s order
    corners.push_back({q[0], q[1], q[2]});
    corners.push_back({q[0], q[2], q[3]});
  }
  const std::unique_ptr<SurfaceQuery> query = aabb_surface_queries()(reference.points, corners);
  std::vector<int> nearest_triangle(at.size());
  std::vector<Vec3> nearest_point(at.size());
  // Asked along a Morton curve, so that neighbouring queries walk the same
  // branches of the tree (a scan's file order jumps about).
  const std::vector<std::size_t> order = morton_order(at);
  parallel_for(at.size(), 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t v = order[i];
      nearest_triangle[v] = query->closest_triangle(at[v], nearest_point[v]);
    }
  });
  auto label = vtkSmartPointer<vtkIntArray>::New();
  label->SetName("label");
  label->SetNumberOfTuples(n);
  auto diffuse = float_array("diffuse", 3, n), specular = float_array("specular", 3, n);
  auto roughness = float_array("roughness", 1, n), displacement = float_array("displacement", 1, n);
  auto moved = vtkSmartPointer<vtkPoints>::New();
  moved->SetDataType(scan->GetPoints()->GetDataType());
  moved->SetNumberOfPoints(n);

  // Every vertex on its own, on every core: GetCell into a cell of each
  // thread's own reads only, once the cells are built.
  triangles->BuildCells();
  std::vector<double> dist2(static_cast<std::size_t>(n)), shift_length(geometry ? std::size_t(n) : 0);
  parallel_for(std::size_t(n), 4096, [&](std::size_t begin, std::size_t end) {
    auto cell = vtkSmartPointer<vtkGenericCell>::New();
    for (vtkIdType v = vtkIdType(begin); v < vtkIdType(end); ++v) {
      double x[3], pcoords[3], weights[3], ignored[3], ignored_dist2 = 0;
      int sub = 0;
      scan->GetPoint(v, x);
      const vtkIdType triangle = nearest_triangle[std::size_t(v)];
      if (triangle < 0)
        throw InputError("the painted surface has no area to transfer from");
      const Vec3& c = nearest_point[std::size_t(v)];
      double closest[3] = {c[0], c[1], c[2]};
      dist2[std::size_t(v)] = (x[0] - closest[0]) * (x[0] - closest[0]) + (x[1] - closest[1]) * (x[1] - closest[1]) +
                              (x[2] - closest[2]) * (x[2] - closest[2]);
      triangles->GetCell(triangle, cell);
      cell->EvaluatePosition(closest, ignored, sub, pcoords, ignored_dist2, weights);
      const auto& q = reference.quads[std::size_t(triangle / 2)];
      const int corner[3] = {q[0], triangle % 2 ? q[2] : q[1], triangle % 2 ? q[3] : q[2]};
      const int nearest = corner[std::max_element(weights, weights + 3) - weights];
      label->SetValue(v, painted.label[std::size_t(nearest)]);
      double d[3] = {0, 0, 0}, s[3] = {0, 0, 0}, r = 0, h = 0, shift[3] = {0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        const std::size_t at_corner = std::size_t(corner[k]);
        const double w = weights[k];
        for (int a = 0; a < 3; ++a) {
          d[a] += w * painted.diffuse[at_corner][a];
          s[a] += w * painted.specular[at_corner][a];
          shift[a] += w * (double(painted.surface.points[at_corner][a]) - reference.points[at_corner][a]);
        }
        r += w * painted.roughness[at_corner];
        h += w * painted.displacement[at_corner];
      }
      diffuse->SetTuple(v, d);
      specular->SetTuple(v, s);
      roughness->SetValue(v, float(r));
      displacement->SetValue(v, float(h));
      if (geometry) {
        // Untouched regions carry exactly zero shift: the vertex stays bit for bit.
        if (shift[0] != 0 || shift[1] != 0 || shift[2] != 0)
          for (int a = 0; a < 3; ++a)
            x[a] += shift[a];
        shift_length[std::size_t(v)] = std::sqrt(shift[0] * shift[0] + shift[1] * shift[1] + shift[2] * shift[2]);
        moved->SetPoint(v, x);
      }
    }
  });
  // Summed in order, so that the report does not depend on the threads.
  TransferReport report;
  double sum2 = 0;
  for (std::size_t v = 0; v < dist2.size(); ++v) {
    report.max_distance = std::max(report.max_distance, std::sqrt(dist2[v]));
    sum2 += dist2[v];
  }
  for (const double moved_by : shift_length)
    report.max_moved = std::max(report.max_moved, moved_by);
  report.rms_distance = n > 0 ? std::sqrt(sum2 / double(n)) : 0.0;
  vtkPointData* pd = scan->GetPointData();
  for (vtkDataArray* a : {static_cast<vtkDataArray*>(label), static_cast<vtkDataArray*>(diffuse),
                          static_cast<vtkDataArray*>(specular), static_cast<vtkDataArray*>(roughness),
                          static_cast<vtkDataArray*>(displacement)}) {
    pd->RemoveArray(a->GetName());
    pd->AddArray(a);
  }
  if (geometry)
    scan->SetPoints(moved);
  return report;
}

void write_transferred_scan(vtkPolyData* scan, const std::string& path, const std::vector<LabelClass>& labels)
{
  const std::string ext = lower_extension(path);
  if (ext == ".ply")
    write_scan_ply(scan, path);
  else if (ext == ".vtp") {
    add_label_classes(scan, labels);
    write_vtp(scan, path);
  } else
    throw InputError("cannot write '" + path + "': unknown format '" + ext + "' (.vtp, .ply)");
}

} // namespace meshpaint
