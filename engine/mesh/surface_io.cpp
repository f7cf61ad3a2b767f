#include "mesh/surface_io.h"

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/format.h"
#include "mesh/openmesh_types.h"
#include "mesh/quiet_openmesh.h"

#include <OpenMesh/Core/IO/MeshIO.hh> // for OpenMesh::IO::write_mesh

#include <sstream> // for std::ostringstream

namespace meshpaint {

void write_surface(const WeldedSurface& s, const std::string& path)
{
  const std::string ext = lower_extension(path);
  if (ext != ".obj" && ext != ".ply")
    throw InputError("cannot write '" + path + "': OpenMesh output is .obj or .ply, not '" + ext + "'");
  PolyMesh mesh;
  const bool normals = !s.normals.empty();
  if (normals)
    mesh.request_vertex_normals();
  mesh.reserve(s.points.size(), 2 * s.quads.size(), s.quads.size());
  for (std::size_t v = 0; v < s.points.size(); ++v) {
    const auto vh = mesh.add_vertex(PolyMesh::Point(s.points[v][0], s.points[v][1], s.points[v][2]));
    if (normals)
      mesh.set_normal(vh, PolyMesh::Normal(s.normals[v][0], s.normals[v][1], s.normals[v][2]));
  }
  for (const auto& q : s.quads)
    mesh.add_face({PolyMesh::VertexHandle(q[0]), PolyMesh::VertexHandle(q[1]),
                   PolyMesh::VertexHandle(q[2]), PolyMesh::VertexHandle(q[3])});
  OpenMesh::IO::Options options;
  if (normals)
    options += OpenMesh::IO::Options::VertexNormal;
  if (ext == ".ply")
    options += OpenMesh::IO::Options::Binary;
  write_openmesh(mesh, path, options);
}

void write_openmesh(const PolyMesh& mesh, const std::string& path, OpenMesh::IO::Options options)
{
  OpenMesh::IO::ExporterT<PolyMesh> exporter(mesh);
  write_exported(exporter, path, options);
}

void write_exported(OpenMesh::IO::BaseExporter& exporter, const std::string& path, OpenMesh::IO::Options options)
{
  std::ostringstream bytes(std::ios::binary);
  {
    QuietOpenMesh quiet;
    if (!OpenMesh::IO::IOManager().write(bytes, lower_extension(path), exporter, options))
      throw IOError("cannot write '" + path + "': OpenMesh could not write it");
  }
  const std::string text = bytes.str();
  write_bytes_atomically(path, {text});
}

} // namespace meshpaint
