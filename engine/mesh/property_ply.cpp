#include "mesh/property_ply.h"

#include "core/errors.h"
#include "mesh/openmesh_types.h"
#include "mesh/surface_io.h"

#include <OpenMesh/Core/IO/exporter/BaseExporter.hh> // for OpenMesh::IO::BaseExporter
#include <OpenMesh/Core/Mesh/BaseKernel.hh>          // for OpenMesh::BaseKernel

namespace meshpaint {
namespace {

using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::EdgeHandle;
using OpenMesh::VertexHandle;
using Status = OpenMesh::Attributes::StatusInfo;

//! The properties alone, sized to the vertices and faces, for OpenMesh's
//! PLY writer, which looks for them in a kernel.
class PropertyKernel : public OpenMesh::BaseKernel
{
public:
  PropertyKernel(std::size_t vertices, std::size_t faces) : vertices_(vertices), faces_(faces) {}
  std::size_t n_vertices() const override { return vertices_; }
  std::size_t n_faces() const override { return faces_; }

  template <template <typename> class Handle, typename T>
  void add(const PlyProperty& p)
  {
    Handle<T> handle;
    add_property(handle, p.name);
    vprops_resize(vertices_);
    fprops_resize(faces_);
    OpenMesh::PropertyT<T>& prop = property(handle);
    prop.set_persistent(true);
    for (std::size_t k = 0; k < p.values.size(); ++k)
      prop[k] = T(p.values[k]);
  }

private:
  std::size_t vertices_, faces_;
};

//! Points and polygons as they are, served to OpenMesh's writers: no
//! half-edge mesh to build (seconds on a scan of millions of triangles),
//! and polygons that would make one non-manifold are written too.
class ArrayExporter : public OpenMesh::IO::BaseExporter
{
public:
  ArrayExporter(const std::vector<Vec3>& points, const std::vector<int>& offsets, const std::vector<int>& corners,
                PropertyKernel& kernel)
      : points_(points), offsets_(offsets), corners_(corners), kernel_(kernel)
  {
  }

  OpenMesh::Vec3f point(VertexHandle v) const override
  {
    const Vec3& p = points_[std::size_t(v.idx())];
    return {p[0], p[1], p[2]};
  }
  OpenMesh::Vec3d pointd(VertexHandle v) const override { return OpenMesh::vector_cast<OpenMesh::Vec3d>(point(v)); }
  bool is_point_double() const override { return false; }
  unsigned int get_vhandles(FaceHandle f, std::vector<VertexHandle>& corners) const override
  {
    corners.clear();
    for (int k = offsets_[std::size_t(f.idx())]; k < offsets_[std::size_t(f.idx()) + 1]; ++k)
      corners.emplace_back(corners_[std::size_t(k)]);
    return unsigned(corners.size());
  }
  const OpenMesh::BaseKernel* kernel() override { return &kernel_; }
  std::size_t n_vertices() const override { return points_.size(); }
  std::size_t n_faces() const override { return offsets_.size() - 1; }
  std::size_t n_edges() const override { return 0; }

  // Nothing else is asked for (the options name no normals, colours,
  // texture coordinates or status).
  OpenMesh::Vec3f normal(VertexHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec3d normald(VertexHandle) const override { return {0, 0, 0}; }
  bool is_normal_double() const override { return false; }
  OpenMesh::Vec3uc color(VertexHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4uc colorA(VertexHandle) const override { return {0, 0, 0, 0}; }
  OpenMesh::Vec3ui colori(VertexHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4ui colorAi(VertexHandle) const override { return {0, 0, 0, 0}; }
  OpenMesh::Vec3f colorf(VertexHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4f colorAf(VertexHandle) const override { return {0, 0, 0, 0}; }
  OpenMesh::Vec2f texcoord(VertexHandle) const override { return {0, 0}; }
  OpenMesh::Vec2f texcoord(HalfedgeHandle) const override { return {0, 0}; }
  Status status(VertexHandle) const override { return {}; }
  HalfedgeHandle getHeh(FaceHandle, VertexHandle) const override { return HalfedgeHandle(); }
  unsigned int get_face_texcoords(std::vector<OpenMesh::Vec2f>&) const override { return 0; }
  OpenMesh::Vec3f normal(FaceHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec3d normald(FaceHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec3uc color(FaceHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4uc colorA(FaceHandle) const override { return {0, 0, 0, 0}; }
  OpenMesh::Vec3ui colori(FaceHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4ui colorAi(FaceHandle) const override { return {0, 0, 0, 0}; }
  OpenMesh::Vec3f colorf(FaceHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4f colorAf(FaceHandle) const override { return {0, 0, 0, 0}; }
  Status status(FaceHandle) const override { return {}; }
  OpenMesh::Vec3uc color(EdgeHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4uc colorA(EdgeHandle) const override { return {0, 0, 0, 0}; }
  OpenMesh::Vec3ui colori(EdgeHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4ui colorAi(EdgeHandle) const override { return {0, 0, 0, 0}; }
  OpenMesh::Vec3f colorf(EdgeHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4f colorAf(EdgeHandle) const override { return {0, 0, 0, 0}; }
  Status status(EdgeHandle) const override { return {}; }
  int get_halfedge_id(VertexHandle) override { return -1; }
  int get_halfedge_id(FaceHandle) override { return -1; }
  int get_next_halfedge_id(HalfedgeHandle) override { return -1; }
  int get_to_vertex_id(HalfedgeHandle) override { return -1; }
  int get_face_id(HalfedgeHandle) override { return -1; }
  Status status(HalfedgeHandle) const override { return {}; }

private:
  const std::vector<Vec3>& points_;
  const std::vector<int>& offsets_;
  const std::vector<int>& corners_;
  PropertyKernel& kernel_;
};

//! Adds the properties to one element kind (vertices or faces).
template <template <typename> class Handle>
void add_properties(PropertyKernel& kernel, const std::vector<PlyProperty>& properties, std::size_t count,
                    const char* what)
{
  for (const PlyProperty& p : properties) {
    if (p.values.size() != count)
      throw InputError("property '" + p.name + "' has " + std::to_string(p.values.size()) + " values for " +
                       std::to_string(count) + " " + what);
    if (p.byte)
      kernel.add<Handle, unsigned char>(p);
    else if (p.integer)
      kernel.add<Handle, int>(p);
    else
      kernel.add<Handle, float>(p);
  }
}

} // namespace

void write_property_ply(const std::vector<Vec3>& points, const std::vector<int>& face_offsets,
                        const std::vector<int>& face_corners, const std::vector<PlyProperty>& vertex_properties,
                        const std::vector<PlyProperty>& face_properties, const std::string& path)
{
  if (face_offsets.empty() || std::size_t(face_offsets.back()) != face_corners.size())
    throw InputError("cannot write '" + path + "': the face offsets do not end at the corner count");
  for (const int v : face_corners)
    if (v < 0 || std::size_t(v) >= points.size())
      throw InputError("cannot write '" + path + "': a face names vertex " + std::to_string(v) + " of " +
                       std::to_string(points.size()));
  const std::size_t faces = face_offsets.size() - 1;
  PropertyKernel kernel(points.size(), faces);
  add_properties<OpenMesh::VPropHandleT>(kernel, vertex_properties, points.size(), "vertices");
  add_properties<OpenMesh::FPropHandleT>(kernel, face_properties, faces, "faces");
  ArrayExporter exporter(points, face_offsets, face_corners, kernel);
  write_exported(exporter, path,
                 OpenMesh::IO::Options(OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::LSB |
                                       OpenMesh::IO::Options::Custom));
}

} // namespace meshpaint
