#include "mesh/property_ply.h"

#include "core/errors.h"
#include "mesh/openmesh_types.h"
#include "mesh/surface_io.h"

namespace meshpaint {
namespace {

//! One property of element kind Handle (vertices or faces), of type T.
template <template <typename> class Handle, typename T>
void add_property(PolyMesh& mesh, const PlyProperty& p)
{
  Handle<T> handle;
  mesh.add_property(handle, p.name);
  OpenMesh::PropertyT<T>& prop = mesh.property(handle);
  prop.set_persistent(true);
  for (std::size_t k = 0; k < p.values.size(); ++k)
    prop[k] = T(p.values[k]);
}

//! Adds the properties to one element kind (vertices or faces) of `mesh`.
template <template <typename> class Handle>
void add_properties(PolyMesh& mesh, const std::vector<PlyProperty>& properties, std::size_t count, const char* what)
{
  for (const PlyProperty& p : properties) {
    if (p.values.size() != count)
      throw InputError("property '" + p.name + "' has " + std::to_string(p.values.size()) + " values for " +
                       std::to_string(count) + " " + what);
    if (p.byte)
      add_property<Handle, unsigned char>(mesh, p);
    else if (p.integer)
      add_property<Handle, int>(mesh, p);
    else
      add_property<Handle, float>(mesh, p);
  }
}

} // namespace

void write_property_ply(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& faces,
                        const std::vector<PlyProperty>& vertex_properties,
                        const std::vector<PlyProperty>& face_properties, const std::string& path)
{
  PolyMesh mesh;
  for (const Vec3& p : points)
    mesh.add_vertex(PolyMesh::Point(p[0], p[1], p[2]));
  std::vector<PolyMesh::VertexHandle> corners;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    corners.clear();
    for (const int v : faces[f])
      corners.emplace_back(v);
    if (!mesh.add_face(corners).is_valid())
      throw InputError("cannot write '" + path + "': face " + std::to_string(f) +
                       " cannot be kept in a PLY file written through OpenMesh (non-manifold); write .vtp instead");
  }
  add_properties<OpenMesh::VPropHandleT>(mesh, vertex_properties, points.size(), "vertices");
  add_properties<OpenMesh::FPropHandleT>(mesh, face_properties, faces.size(), "faces");
  write_openmesh(mesh, path, OpenMesh::IO::Options(OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::LSB |
                                                     OpenMesh::IO::Options::Custom));
}

} // namespace meshpaint
