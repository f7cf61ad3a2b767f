#include "SurfaceConversion.h"

#include "core/atomic_file.h" // for meshpaint::write_bytes_atomically
#include "core/errors.h"      // for meshpaint::IOError

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::floor
#include <cstring>   // for std::memcmp, std::memcpy
#include <stdexcept>   // for std::invalid_argument
#include <type_traits> // for std::remove_pointer_t

#include <vtkCellArray.h>          // for vtkCellArray
#include <vtkFieldData.h>          // for vtkFieldData
#include <vtkFloatArray.h>         // for vtkFloatArray
#include <vtkIdTypeArray.h>        // for vtkIdTypeArray
#include <vtkImageData.h>          // for vtkImageData
#include <vtkIntArray.h>           // for vtkIntArray
#include <vtkPNGWriter.h>          // for vtkPNGWriter
#include <vtkPointData.h>          // for vtkPointData
#include <vtkPoints.h>             // for vtkPoints
#include <vtkNew.h>                // for vtkNew
#include <vtkPolyData.h>           // for vtkPolyData
#include <vtkStringArray.h>        // for vtkStringArray
#include <vtkUnsignedCharArray.h>  // for vtkUnsignedCharArray
#include <vtkXMLPolyDataWriter.h>  // for vtkXMLPolyDataWriter

namespace meshpaint {
namespace {

vtkSmartPointer<vtkFloatArray> vec3_array(const std::vector<Vec3>& v, const char* name)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(vtkIdType(v.size()));
  std::copy(&v[0][0], &v[0][0] + 3 * v.size(), a->GetPointer(0));
  return a;
}

} // namespace

vtkSmartPointer<vtkPolyData> to_polydata(const WeldedSurface& s)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  if (!s.points.empty())
    points->SetData(vec3_array(s.points, "Points"));
  poly->SetPoints(points);

  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(vtkIdType(s.quads.size() + 1));
  connectivity->SetNumberOfValues(vtkIdType(4 * s.quads.size()));
  for (std::size_t q = 0; q <= s.quads.size(); ++q)
    offsets->SetValue(vtkIdType(q), vtkIdType(4 * q));
  for (std::size_t q = 0; q < s.quads.size(); ++q)
    for (int k = 0; k < 4; ++k)
      connectivity->SetValue(vtkIdType(4 * q + k), s.quads[q][k]);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  poly->SetPolys(cells);

  if (!s.normals.empty())
    poly->GetPointData()->SetNormals(vec3_array(s.normals, "Normals"));
  return poly;
}

vtkSmartPointer<vtkPolyData> to_polydata(const PaintedSurface& s)
{
  vtkSmartPointer<vtkPolyData> poly = to_polydata(s.surface);
  vtkPointData* pd = poly->GetPointData();
  pd->AddArray(vec3_array(s.diffuse, "diffuse"));
  pd->AddArray(vec3_array(s.specular, "specular"));
  if (!s.inside_diffuse.empty()) { // two-sided
    pd->AddArray(vec3_array(s.inside_diffuse, "inside_diffuse"));
    pd->AddArray(vec3_array(s.inside_specular, "inside_specular"));
  }
  for (const auto& [values, name] : {std::pair{&s.roughness, "roughness"}, std::pair{&s.displacement, "displacement"},
                                     std::pair{&s.mask, "mask"}, std::pair{&s.inside_roughness, "inside_roughness"}}) {
    if (values->empty())
      continue;
    auto a = vtkSmartPointer<vtkFloatArray>::New();
    a->SetName(name);
    a->SetNumberOfValues(vtkIdType(values->size()));
    std::copy(values->begin(), values->end(), a->GetPointer(0));
    pd->AddArray(a);
  }
  auto label = vtkSmartPointer<vtkIntArray>::New();
  label->SetName("label");
  label->SetNumberOfValues(vtkIdType(s.label.size()));
  std::copy(s.label.begin(), s.label.end(), label->GetPointer(0));
  pd->AddArray(label);
  return poly;
}

namespace {

//! Copies `count` values of `from` into `to` (an array of as many values)
//! unless they are equal already; true when it copied.
template <typename T>
bool copy_if_changed(vtkDataArray* to, const T* from, std::size_t count)
{
  if (!to || std::size_t(to->GetNumberOfValues()) != count)
    throw std::invalid_argument("update_polydata: the surface does not match the polydata");
  T* values = static_cast<T*>(to->GetVoidPointer(0));
  if (count == 0 || std::memcmp(values, from, count * sizeof(T)) == 0)
    return false;
  std::memcpy(values, from, count * sizeof(T));
  to->Modified();
  return true;
}

} // namespace

namespace {

//! Calls f(array of poly, values, components) for the points, the normals
//! and every channel array `s` has values for, in one order for every
//! update: the arrays to_polydata() made.
template <typename F>
void for_each_array(vtkPolyData* poly, const PaintedSurface& s, F f)
{
  vtkPointData* pd = poly->GetPointData();
  f(poly->GetPoints()->GetData(), s.surface.points.data()->data(), 3);
  if (!s.surface.normals.empty())
    f(pd->GetNormals(), s.surface.normals.data()->data(), 3);
  f(pd->GetArray("diffuse"), s.diffuse.data()->data(), 3);
  f(pd->GetArray("specular"), s.specular.data()->data(), 3);
  f(pd->GetArray("roughness"), s.roughness.data(), 1);
  f(pd->GetArray("displacement"), s.displacement.data(), 1);
  f(pd->GetArray("mask"), s.mask.data(), 1);
  f(pd->GetArray("label"), s.label.data(), 1);
  if (!s.inside_diffuse.empty() && pd->GetArray("inside_diffuse")) {
    f(pd->GetArray("inside_diffuse"), s.inside_diffuse.data()->data(), 3);
    f(pd->GetArray("inside_specular"), s.inside_specular.data()->data(), 3);
    f(pd->GetArray("inside_roughness"), s.inside_roughness.data(), 1);
  }
}

} // namespace

int update_polydata(vtkPolyData* poly, const PaintedSurface& s)
{
  int changed = 0;
  const std::size_t count = s.surface.points.size();
  for_each_array(poly, s, [&](vtkDataArray* to, const auto* from, int components) {
    changed += copy_if_changed(to, from, count * std::size_t(components));
  });
  return changed; // the polydata's time includes its arrays', so renderers notice
}

namespace {

//! Writes `components` values per listed vertex into `to`; marks it modified
//! when any differed. True when it did.
template <typename T>
bool scatter_if_changed(vtkDataArray* to, const std::vector<int>& ids, const T* from, int components)
{
  if (ids.empty())
    return false;
  if (!to || to->GetNumberOfComponents() != components)
    throw std::invalid_argument("update_polydata: the vertices do not match the polydata");
  const vtkIdType tuples = to->GetNumberOfTuples();
  T* values = static_cast<T*>(to->GetVoidPointer(0));
  bool changed = false;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (ids[k] < 0 || ids[k] >= tuples)
      throw std::invalid_argument("update_polydata: a vertex beyond the polydata's points");
    T* at = values + std::size_t(ids[k]) * components;
    const T* value = from + k * components;
    if (std::memcmp(at, value, sizeof(T) * components) != 0) {
      std::memcpy(at, value, sizeof(T) * components);
      changed = true;
    }
  }
  if (changed)
    to->Modified();
  return changed;
}

} // namespace

int update_polydata(vtkPolyData* poly, const PaintedVertices& update)
{
  if (update.ids.empty())
    return 0;
  int changed = 0;
  for_each_array(poly, update.values, [&](vtkDataArray* to, const auto* from, int components) {
    changed += scatter_if_changed(to, update.ids, from, components);
  });
  return changed; // vtkPoints::Modified() would mark the points too: the arrays say it
}

BaseMesh to_base_mesh(vtkPolyData* poly, const std::string& name)
{
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  if (poly && poly->GetPoints())
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
      double p[3];
      poly->GetPoint(i, p);
      points.push_back({float(p[0]), float(p[1]), float(p[2])});
    }
  if (poly && poly->GetPolys()) {
    vtkCellArray* polys = poly->GetPolys();
    vtkIdType npts;
    const vtkIdType* ids;
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
      faces.emplace_back(ids, ids + npts);
  }
  return make_base_mesh(std::move(points), faces, name);
}

namespace {

//! One map as an image: `components` floats per pixel in 0..1 (after
//! (v - offset) * scale), rows top first, quantised to 8 or 16 bits.
vtkSmartPointer<vtkImageData> map_image(const std::vector<float>& values, int width, int height, int components,
                                        bool sixteen, float offset, float scale)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(sixteen ? VTK_UNSIGNED_SHORT : VTK_UNSIGNED_CHAR, components);
  // Straight into the scalars: a SetScalarComponentFromDouble() per value
  // (a virtual lookup of the array and the index each time) had been most
  // of a texture map's time.
  const auto quantise = [&](auto* out, double top) {
    const std::size_t row = std::size_t(width) * std::size_t(components);
    for (int y = 0; y < height; ++y) { // VTK's row 0 is the bottom of the picture
      const float* in = values.data() + std::size_t(y) * row;
      auto* to = out + std::size_t(height - 1 - y) * row;
      for (std::size_t k = 0; k < row; ++k) {
        const double q = std::min(1.0, std::max(0.0, double((in[k] - offset) * scale))) * top + 0.5;
        to[k] = static_cast<std::remove_pointer_t<decltype(out)>>(std::floor(q));
      }
    }
  };
  if (sixteen)
    quantise(static_cast<unsigned short*>(image->GetScalarPointer()), 65535.0);
  else
    quantise(static_cast<unsigned char*>(image->GetScalarPointer()), 255.0);
  return image;
}

void write_png(const std::vector<float>& values, int width, int height, int components, bool sixteen,
               float offset, float scale, const std::string& path)
{
  const std::string png = png_bytes(map_image(values, width, height, components, sixteen, offset, scale), path);
  write_bytes_atomically(path, {png});
}

} // namespace

std::string png_bytes(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* result = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !result || result->GetNumberOfValues() == 0)
    throw IOError("cannot write '" + path + "': the PNG could not be encoded");
  return std::string(reinterpret_cast<const char*>(result->GetPointer(0)), std::size_t(result->GetNumberOfValues()));
}

std::string map_png(const std::vector<float>& values, int width, int height, int components, const std::string& path)
{
  return png_bytes(map_image(values, width, height, components, false, 0.f, 1.f), path);
}

void write_texture_maps(const TextureMaps& maps, const std::string& dir)
{
  write_png(maps.diffuse, maps.width, maps.height, 3, false, 0.f, 1.f, dir + "/diffuse.png");
  write_png(maps.specular, maps.width, maps.height, 3, false, 0.f, 1.f, dir + "/specular.png");
  write_png(maps.roughness, maps.width, maps.height, 1, false, 0.f, 1.f, dir + "/roughness.png");
  if (!maps.inside_diffuse.empty()) {
    write_png(maps.inside_diffuse, maps.width, maps.height, 3, false, 0.f, 1.f, dir + "/inside_diffuse.png");
    write_png(maps.inside_specular, maps.width, maps.height, 3, false, 0.f, 1.f, dir + "/inside_specular.png");
    write_png(maps.inside_roughness, maps.width, maps.height, 1, false, 0.f, 1.f, dir + "/inside_roughness.png");
  }
  const float range = maps.displacement_max - maps.displacement_min;
  write_png(maps.displacement, maps.width, maps.height, 1, true, maps.displacement_min,
            range > 0.f ? 1.f / range : 0.f, dir + "/displacement.png");
}

void write_vtp(vtkPolyData* poly, const std::string& path)
{
  // Encoded in memory, then written by us: VTK's writer reports a full disk
  // only on its own console, several lines long.
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(poly);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->WriteToOutputStringOn();
  if (!writer->Write())
    throw IOError("cannot write '" + path + "': VTK could not encode the surface");
  const std::string bytes = writer->GetOutputString();
  write_bytes_atomically(path, {bytes});
}

void add_label_classes(vtkPolyData* poly, const std::vector<LabelClass>& labels)
{
  auto ids = vtkSmartPointer<vtkIntArray>::New();
  ids->SetName("label_ids");
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("label_names");
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetName("label_colors");
  colours->SetNumberOfComponents(3);
  for (const LabelClass& label : labels) {
    ids->InsertNextValue(label.id);
    names->InsertNextValue(label.name);
    for (int c = 0; c < 3; ++c)
      colours->InsertNextValue(colour_byte(label.colour[c]));
  }
  vtkFieldData* fd = poly->GetFieldData();
  for (vtkAbstractArray* a : {static_cast<vtkAbstractArray*>(ids), static_cast<vtkAbstractArray*>(names),
                              static_cast<vtkAbstractArray*>(colours)}) {
    fd->RemoveArray(a->GetName());
    fd->AddArray(a);
  }
}

unsigned char colour_byte(float value)
{
  return static_cast<unsigned char>(std::floor(std::min(1.0, std::max(0.0, double(value))) * 255.0 + 0.5));
}

} // namespace meshpaint
