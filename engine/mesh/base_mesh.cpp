#include "mesh/base_mesh.h"

#include "core/errors.h"
#include "core/format.h"
#include "mesh/file_census.h"
#include "mesh/off_reader.h"
#include "mesh/openmesh_types.h"
#include "mesh/quiet_openmesh.h"
#include "mesh/soup_import.h"

#include <OpenMesh/Core/IO/IOManager.hh>          // for OpenMesh::IO::IOManager
#include <OpenMesh/Core/IO/importer/ImporterT.hh> // for OpenMesh::IO::ImporterT

#include <algorithm>  // for std::transform, std::min, std::max, std::min_element
#include <cmath>      // for std::isfinite, std::sqrt, std::fabs
#include <cstdint>    // for std::int32_t, std::uint8_t, std::int8_t, std::int16_t, std::uint16_t
#include <filesystem> // for std::filesystem
#include <map>        // for std::map
#include <numeric>    // for std::iota
#include <set>        // for std::set
#include <fstream>    // for std::ifstream
#include <iterator>   // for std::istreambuf_iterator
#include <sstream>    // for std::ostringstream, std::istringstream

namespace meshpaint {
namespace {

//! OpenMesh's importer, counting what it repairs and stopping at faces that
//! name vertices the file does not have (OpenMesh would drop them silently).
class CheckedImporter : public OpenMesh::IO::ImporterT<PolyMesh>
{
public:
  explicit CheckedImporter(PolyMesh& mesh) : ImporterT<PolyMesh>(mesh), mesh_(mesh) {}

  OpenMesh::FaceHandle add_face(const VHandles& indices) override
  {
    const std::size_t face = faces_++;
    for (const OpenMesh::VertexHandle vh : indices)
      if (!mesh_.is_valid_handle(vh)) {
        if (problem_.empty())
          problem_ = "face " + std::to_string(face) + " names vertex " +
                     std::to_string(vh.idx()) + ", but there are only " +
                     std::to_string(mesh_.n_vertices()) + " vertices";
        return OpenMesh::FaceHandle();
      }
    bool repeated = indices.size() < 3;
    for (std::size_t a = 0; a < indices.size() && !repeated; ++a)
      for (std::size_t b = a + 1; b < indices.size(); ++b)
        repeated = repeated || indices[a] == indices[b];
    if (repeated) {
      ++report.degenerate_faces_dropped;
      return OpenMesh::FaceHandle();
    }
    // A second copy of a face would be detached as non-manifold and leave a
    // loose sheet on the surface; it adds nothing, so it goes.
    if (!seen_.insert(cyclic_key(indices)).second) {
      ++report.duplicate_faces_dropped;
      return OpenMesh::FaceHandle();
    }
    const std::size_t before = mesh_.n_vertices();
    const OpenMesh::FaceHandle fh = ImporterT<PolyMesh>::add_face(indices);
    if (mesh_.n_vertices() != before) {
      ++report.nonmanifold_faces_detached; // OpenMesh gave the face its own vertices, one per corner
      for (std::size_t k = 0; k < indices.size() && before + k < mesh_.n_vertices(); ++k)
        copied_from.emplace(int(before + k), indices[k].idx());
    }
    return fh;
  }

  std::size_t faces_seen() const { return faces_; }

  ImportReport report;
  std::string problem_;
  std::map<int, int> copied_from; //!< vertex copies OpenMesh made -> the vertex copied

private:
  //! The corners from the smallest index on, in the direction of its
  //! smaller neighbour: equal for a face and its copies, either orientation.
  static std::vector<int> cyclic_key(const VHandles& f)
  {
    const std::size_t n = f.size();
    const std::size_t m = std::size_t(std::min_element(f.begin(), f.end()) - f.begin());
    const bool forward = f[(m + 1) % n].idx() < f[(m + n - 1) % n].idx();
    std::vector<int> key(n);
    for (std::size_t k = 0; k < n; ++k)
      key[k] = f[forward ? (m + k) % n : (m + n - k) % n].idx();
    return key;
  }

  PolyMesh& mesh_;
  std::size_t faces_ = 0;
  std::set<std::vector<int>> seen_; // cyclic_key of every face added
};

//! OpenMesh's readers into a PolygonSoup: vertices (and their colours)
//! through the mesh, faces only recorded, so that import_soup() sees the
//! file's faces as they are, whatever their orientation.
class SoupImporter : public OpenMesh::IO::ImporterT<PolyMesh>
{
public:
  explicit SoupImporter(PolyMesh& mesh) : ImporterT<PolyMesh>(mesh), mesh_(mesh) {}

  OpenMesh::FaceHandle add_face(const VHandles& indices) override
  {
    const std::size_t face = faces.size();
    std::vector<int> f;
    for (const OpenMesh::VertexHandle vh : indices) {
      if (!mesh_.is_valid_handle(vh)) {
        if (problem.empty())
          problem = "face " + std::to_string(face) + " names vertex " + std::to_string(vh.idx()) +
                    ", but there are only " + std::to_string(mesh_.n_vertices()) + " vertices";
        return OpenMesh::FaceHandle();
      }
      f.push_back(vh.idx());
    }
    faces.push_back(std::move(f));
    return OpenMesh::FaceHandle();
  }

  // OpenMesh's OBJ reader colours the vertices a face names as it reads the
  // face, before anything checks that they exist.
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3uc& c) override { colour_if_valid(vh, c); }
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4uc& c) override { colour_if_valid(vh, c); }
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& c) override { colour_if_valid(vh, c); }
  void set_color(OpenMesh::VertexHandle vh, const OpenMesh::Vec4f& c) override { colour_if_valid(vh, c); }
  using ImporterT<PolyMesh>::set_color;

  std::vector<std::vector<int>> faces;
  std::string problem;

private:
  template <class Colour>
  void colour_if_valid(OpenMesh::VertexHandle vh, const Colour& c)
  {
    if (mesh_.is_valid_handle(vh)) {
      ImporterT<PolyMesh>::set_color(vh, c);
    } else if (problem.empty()) {
      problem = "a colour for vertex " + std::to_string(vh.idx()) + ", but there are only " +
                std::to_string(mesh_.n_vertices()) + " vertices";
    }
  }

  PolyMesh& mesh_;
};

std::string vertex_text(const Vec3& p)
{
  std::ostringstream s;
  s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return s.str();
}

//! \throw InputError when a coordinate of vertex `v` is not finite or beyond kMaxCoordinate.
void check_coordinates(const Vec3& p, std::size_t v, const std::string& where)
{
  if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    throw InputError(where + "vertex " + std::to_string(v) + " has a non-finite coordinate " + vertex_text(p));
  if (std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])}) > kMaxCoordinate)
    throw InputError(where + "vertex " + std::to_string(v) + " has a coordinate beyond +-1e15 " + vertex_text(p) +
                     ": limit normals would overflow single precision; scale the mesh down");
}

//! Union-find over the corners around one vertex.
struct Fans
{
  std::vector<int> parent;
  int find(int a) { return parent[a] == a ? a : parent[a] = find(parent[a]); }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

//! Gives every extra surface sheet that meets at a vertex its own copy of it.
void split_nonmanifold_vertices(BaseMesh& mesh)
{
  const std::size_t nv = mesh.points.size();
  std::vector<std::vector<std::pair<int, int>>> corners(nv); // (face, corner)
  for (std::size_t f = 0; f < mesh.face_sizes.size(); ++f)
    for (int k = 0; k < mesh.face_sizes[f]; ++k)
      corners[mesh.face_vertices[mesh.face_offsets[f] + k]].push_back({int(f), k});

  for (std::size_t v = 0; v < nv; ++v) {
    const auto& cs = corners[v];
    if (cs.size() < 2)
      continue;
    Fans fans{std::vector<int>(cs.size())};
    std::iota(fans.parent.begin(), fans.parent.end(), 0);
    std::map<int, int> by_neighbour; // neighbour vertex -> a corner using that edge
    for (std::size_t c = 0; c < cs.size(); ++c) {
      const int f = cs[c].first, k = cs[c].second, n = mesh.face_sizes[f];
      const int* fv = &mesh.face_vertices[mesh.face_offsets[f]];
      for (const int w : {fv[(k + 1) % n], fv[(k + n - 1) % n]}) {
        const auto [it, fresh] = by_neighbour.emplace(w, int(c));
        if (!fresh)
          fans.join(int(c), it->second);
      }
    }
    std::map<int, int> copy_of_root;
    for (std::size_t c = 0; c < cs.size(); ++c) {
      const int root = fans.find(int(c));
      if (copy_of_root.empty())
        copy_of_root[root] = int(v);
      auto it = copy_of_root.find(root);
      if (it == copy_of_root.end()) {
        it = copy_of_root.emplace(root, int(mesh.points.size())).first;
        mesh.points.push_back(mesh.points[v]);
        if (!mesh.colours.empty())
          mesh.colours.push_back(mesh.colours[v]);
        if (!mesh.labels.empty())
          mesh.labels.push_back(mesh.labels[v]);
        append_vertex(mesh.channels, mesh.channels, v);
        ++mesh.report.nonmanifold_vertices_split;
      }
      mesh.face_vertices[mesh.face_offsets[cs[c].first] + cs[c].second] = it->second;
    }
  }
}

//! A base mesh of the vertices that `faces` use, in their order: checks
//! coordinates, drops unused vertices, carries colours, labels and
//! channels (a vertex copy's from `copied_from`). `point(v)` gives vertex
//! v; `faces(visit)` calls visit(corners) once per face, in order.
template <typename PointOf, typename Faces>
BaseMesh assemble(std::size_t vertices, const PointOf& point, const Faces& faces, const ImportReport& report,
                  const std::string& name, const std::string& where, const std::vector<Vec3>& colours,
                  const std::vector<int>& labels, const std::vector<ChannelArray>& channels,
                  const std::map<int, int>& copied_from)
{
  BaseMesh mesh;
  mesh.name = name;
  mesh.report = report;
  mesh.channels = without_values(channels);
  std::vector<int> remap(vertices, -1);
  std::size_t face_count = 0;
  faces([&](const auto& corners) {
    ++face_count;
    for (const int v : corners)
      remap[std::size_t(v)] = 0;
  });
  if (face_count == 0)
    throw InputError(where + "has no faces");
  for (std::size_t v = 0; v < vertices; ++v) {
    const Vec3 p = point(v);
    check_coordinates(p, v, where);
    if (remap[v] < 0) {
      ++mesh.report.isolated_vertices_removed;
      continue;
    }
    remap[v] = int(mesh.points.size());
    mesh.points.push_back(p);
    const auto copy = copied_from.find(int(v));
    const std::size_t source = std::size_t(copy == copied_from.end() ? int(v) : copy->second);
    if (!colours.empty())
      mesh.colours.push_back(colours[source]);
    if (!labels.empty())
      mesh.labels.push_back(labels[source]);
    append_vertex(mesh.channels, channels, source);
  }
  mesh.face_sizes.reserve(face_count);
  mesh.face_offsets.reserve(face_count + 1);
  mesh.face_offsets.push_back(0);
  faces([&](const auto& corners) {
    int n = 0;
    for (const int v : corners) {
      mesh.face_vertices.push_back(remap[std::size_t(v)]);
      ++n;
    }
    mesh.face_sizes.push_back(n);
    mesh.face_offsets.push_back(int(mesh.face_vertices.size()));
  });
  return mesh;
}

//! Takes the faces out of OpenMesh (assemble()) and splits non-manifold vertices.
BaseMesh finish(const PolyMesh& om, const ImportReport& report, const std::string& name,
                const std::string& where, const std::vector<Vec3>& colours, const std::vector<int>& labels,
                const std::vector<ChannelArray>& channels, const std::map<int, int>& copied_from)
{
  const auto point = [&](std::size_t v) {
    const auto& p = om.point(PolyMesh::VertexHandle(int(v)));
    return Vec3{p[0], p[1], p[2]};
  };
  const auto faces = [&](const auto& visit) {
    std::vector<int> corners;
    for (const auto fh : om.faces()) {
      corners.clear();
      for (const auto vh : om.fv_range(fh))
        corners.push_back(vh.idx());
      visit(corners);
    }
  };
  BaseMesh mesh =
      assemble(om.n_vertices(), point, faces, report, name, where, colours, labels, channels, copied_from);
  split_nonmanifold_vertices(mesh);
  return mesh;
}

//! Refuses a mesh too small for single precision's limit normals.
void check_extent(const BaseMesh& mesh, const std::string& where)
{
  if (!(mesh.diagonal() >= kMinDiagonal)) {
    std::ostringstream size;
    size << mesh.diagonal();
    throw InputError(where + "is only " + size.str() + " across: its limit normals would underflow single precision; "
                     "scale the mesh up (at least 1e-12 across)");
  }
}

} // namespace

bool ImportReport::changed() const
{
  return faces_skipped_by_reader || degenerate_faces_dropped || duplicate_faces_dropped || nonmanifold_faces_detached ||
         nonmanifold_vertices_split || isolated_vertices_removed;
}

std::vector<std::string> ImportReport::lines() const
{
  std::vector<std::string> out;
  if (faces_skipped_by_reader)
    out.push_back("dropped " + counted(faces_skipped_by_reader, "face", "faces") +
                  " the file lists but the reader could not use (repeated or missing vertices)");
  if (degenerate_faces_dropped)
    out.push_back("dropped " + counted(degenerate_faces_dropped, "degenerate face", "degenerate faces") +
                  " (a vertex named twice, or fewer than 3 vertices)");
  if (duplicate_faces_dropped)
    out.push_back("dropped " + counted(duplicate_faces_dropped, "duplicate face", "duplicate faces") +
                  " (the corners of an earlier face, in either orientation)");
  if (nonmanifold_faces_detached)
    out.push_back("detached " + counted(nonmanifold_faces_detached, "face that does", "faces that do") +
                  " not join their neighbours (an edge with more than two faces, or "
                  "faces of opposite orientation); each keeps its own copies of its vertices");
  if (nonmanifold_vertices_split)
    out.push_back("split " + counted(nonmanifold_vertices_split, "non-manifold vertex", "non-manifold vertices") +
                  " (one copy per extra surface sheet)");
  if (isolated_vertices_removed)
    out.push_back("removed " + counted(isolated_vertices_removed, "vertex", "vertices") + " used by no face");
  return out;
}

std::vector<std::string> ImportReport::step_lines(const std::string& source, const std::string& weld_off) const
{
  const std::string sources = source + "'s";
  std::vector<std::string> out;
  if (vertices_welded) {
    std::ostringstream t;
    t << weld_tolerance;
    out.push_back("welded " + counted(vertices_welded, "coincident vertex", "coincident vertices") + " (within " +
                  t.str() + "; " + weld_off + " keeps them)");
  }
  if (faces_flipped)
    out.push_back("turned " + counted(faces_flipped, "face", "faces") + " to agree with their neighbours");
  if (components_turned_outward)
    out.push_back("turned " +
                  counted(components_turned_outward, "closed component wound inwards", "closed components wound inwards") +
                  " outward");
  if (nonorientable_components)
    out.push_back("cut " +
                  counted(nonorientable_components, "non-orientable or non-manifold component",
                        "non-orientable or non-manifold components") +
                  " open at " + counted(vertices_cut, "vertex copy", "vertex copies") + " to orient them");
  const std::string vertices = counted(array_vertices, "vertex", "vertices");
  if (coloured && colour_array.empty())
    out.push_back("took " + sources + " colours as the diffuse channel");
  if (coloured && !colour_array.empty())
    out.push_back("took " + sources + " '" + excerpt(colour_array) + "' array as the diffuse channel (" + vertices + ")");
  for (const auto& [array, channel] : channel_arrays)
    out.push_back("took " + sources + " '" + excerpt(array) + "' array as the " + channel + " channel (" + vertices + ")");
  if (!label_array.empty())
    out.push_back("took " + sources + " '" + excerpt(label_array) + "' array as the label channel (" +
                  counted(label_classes, "class", "classes") + ")");
  if (named_label_classes)
    out.push_back("took the names and colours of " + counted(named_label_classes, "label class", "label classes") +
                  " from " + source);
  return out;
}

std::size_t BaseMesh::triangle_count() const
{
  std::size_t n = 0;
  for (const int size : face_sizes)
    n += std::size_t(size - 2);
  return n;
}

double BaseMesh::diagonal() const
{
  return diagonal_of(points);
}

const std::vector<std::string>& readable_mesh_extensions()
{
  static const std::vector<std::string> exts = {".obj", ".off", ".ply", ".stl"};
  return exts;
}

namespace {

//! make_base_mesh() with the prefix its messages carry.
BaseMesh build(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& faces, const std::string& name,
               const std::string& where, const std::vector<Vec3>& colours, const std::vector<int>& labels = {},
               const std::vector<ChannelArray>& channels = {})
{
  if (points.empty() || faces.empty())
    throw InputError(where + "has no faces");
  PolyMesh om;
  CheckedImporter importer(om);
  QuietOpenMesh quiet;
  for (const Vec3& p : points)
    importer.add_vertex(PolyMesh::Point(p[0], p[1], p[2]));
  for (const auto& f : faces) {
    CheckedImporter::VHandles vh;
    for (const int i : f)
      vh.push_back(PolyMesh::VertexHandle(i));
    importer.add_face(vh);
    if (!importer.problem_.empty())
      throw InputError(where + importer.problem_);
  }
  BaseMesh mesh = finish(om, importer.report, name, where, colours, labels, channels, importer.copied_from);
  check_extent(mesh, where);
  return mesh;
}

//! Whether an OFF file is binary: OpenMesh's rule, BINARY on the first line.
bool binary_off(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string first;
  std::getline(in, first);
  return first.find("BINARY") != std::string::npos;
}

//! OpenMesh's PLY reader takes only some spellings of a list's types
//! (uchar, uint16, int): each list type becomes the one of its size that it
//! takes. The census has bounded every count and index, so the values read
//! the same either way. In a text file, a one-byte property of its own
//! becomes int, which OpenMesh reads as a number rather than a character.
//! Returns whether the file has properties of its own (beyond coordinates,
//! normals, colours and texture coordinates), which OpenMesh reads only
//! when asked.
bool normalise_ply_types(std::string& bytes, bool text)
{
  bool own = false;
  const std::size_t end = bytes.find("end_header");
  if (end == std::string::npos)
    return false;
  std::istringstream header(bytes.substr(0, end));
  std::string out, line;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;)
      w.push_back(word);
    if (w.size() == 5 && w[0] == "property" && w[1] == "list") {
      for (std::string* t : {&w[2], &w[3]}) {
        static const std::map<std::string, std::string> same_size = {
          {"char", "uchar"},   {"int8", "uchar"},   {"uint8", "uchar"},  {"short", "uint16"},
          {"ushort", "uint16"}, {"int16", "uint16"}, {"uint", "int"},    {"int32", "int"}, {"uint32", "int"}};
        const auto it = same_size.find(*t);
        if (it != same_size.end())
          *t = it->second;
      }
      line = "property list " + w[2] + " " + w[3] + " " + w[4];
    }
    if (w.size() == 3 && w[0] == "property") {
      static const std::set<std::string> standard = {
        "x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha", "u", "v", "s", "t",
        "texture_u", "texture_v", "texture_s", "texture_t", "diffuse_red", "diffuse_green", "diffuse_blue"};
      static const std::set<std::string> bytes_wide = {"char", "uchar", "int8", "uint8"};
      const bool custom = standard.count(w[2]) == 0;
      if (custom && text && bytes_wide.count(w[1]))
        line = "property int " + w[2];
      own = own || custom;
    }
    out += line + "\n";
  }
  bytes = out + bytes.substr(end);
  return own;
}

//! The ids of the custom vertex property `name` if OpenMesh's PLY reader made
//! it with integer type T; false otherwise.
template <typename T>
bool integer_property(const PolyMesh& om, const std::string& name, std::vector<int>& ids)
{
  OpenMesh::VPropHandleT<T> handle;
  if (!om.get_property_handle(handle, name))
    return false;
  ids.clear();
  for (const auto vh : om.vertices())
    ids.push_back(int(om.property(handle, vh)));
  return true;
}

//! The vertex property `name` as a VertexArray if OpenMesh's PLY reader made
//! it with type T; false otherwise.
template <typename T>
bool vertex_array(const PolyMesh& om, const std::string& name, bool integer, std::vector<VertexArray>& arrays)
{
  OpenMesh::VPropHandleT<T> handle;
  if (!om.get_property_handle(handle, name))
    return false;
  VertexArray a;
  a.name = name;
  a.integer = integer;
  a.values.reserve(om.n_vertices());
  for (const auto vh : om.vertices())
    a.values.push_back(double(om.property(handle, vh)));
  arrays.push_back(std::move(a));
  return true;
}

//! Every numeric vertex property of the file's own, in the header's order,
//! with component properties joined (join_component_arrays()).
void read_ply_arrays(const PolyMesh& om, PolygonSoup& soup)
{
  std::vector<std::string> names;
  for (auto it = om.vprops_begin(); it != om.vprops_end(); ++it)
    if (*it && (*it)->name().compare(0, 2, "v:") != 0) // OpenMesh's own properties are named "v:..."
      names.push_back((*it)->name());
  for (const std::string& name : names)
    vertex_array<float>(om, name, false, soup.arrays) || vertex_array<double>(om, name, false, soup.arrays) ||
      vertex_array<std::int32_t>(om, name, true, soup.arrays) || vertex_array<std::uint32_t>(om, name, true, soup.arrays) ||
      vertex_array<std::int16_t>(om, name, true, soup.arrays) || vertex_array<std::uint16_t>(om, name, true, soup.arrays) ||
      vertex_array<std::int8_t>(om, name, true, soup.arrays) || vertex_array<std::uint8_t>(om, name, true, soup.arrays);
  join_component_arrays(soup.arrays);
}

//! The first integer vertex property named as label_array_names() lists,
//! as the soup's labels (a float property of that name is not labels).
void read_ply_labels(const PolyMesh& om, PolygonSoup& soup)
{
  for (const std::string& name : label_array_names()) {
    std::vector<int> ids;
    if (integer_property<std::int32_t>(om, name, ids) || integer_property<std::uint8_t>(om, name, ids) ||
        integer_property<std::int8_t>(om, name, ids) || integer_property<std::int16_t>(om, name, ids) ||
        integer_property<std::uint16_t>(om, name, ids)) {
      soup.labels = std::move(ids);
      soup.label_array = name;
      return;
    }
  }
}

//! A file through OpenMesh's reader for its format, after the census: the
//! vertices with their colours, the faces as listed.
PolygonSoup read_through_openmesh(const std::string& path, const std::string& ext, const std::string& where)
{
  // OpenMesh's text readers skip a vertex written as "nan" or "inf"; say so
  // rather than let the faces after it name the wrong vertices.
  const FileCensus census = take_census(path, ext);
  if (!census.problem.empty())
    throw InputError(where + census.problem);
  if (census.nonfinite_line >= 0)
    throw InputError(where + "line " + std::to_string(census.nonfinite_line) + ": non-finite coordinate '" +
                     census.nonfinite_token + "'");

  PolyMesh om;
  om.request_vertex_colors();
  SoupImporter importer(om);
  // STL has no vertex colours, but OpenMesh's STL reader leaves the request
  // standing in the options as if the file had them: ask only other formats.
  OpenMesh::IO::Options options;
  if (ext != ".stl")
    options += OpenMesh::IO::Options::VertexColor;
  if (census.binary)
    options += OpenMesh::IO::Options::Binary;
  bool ok = false;
  {
    // From memory, past a UTF-8 byte-order mark, which OpenMesh would read
    // as part of the first word.
    std::ifstream file(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (census.text && bytes.compare(0, 3, "\xEF\xBB\xBF") == 0)
      bytes.erase(0, 3);
    if (ext == ".ply" && normalise_ply_types(bytes, census.text))
      options += OpenMesh::IO::Options::Custom; // the file's own properties, for the label and other channels
    std::istringstream in(std::move(bytes), std::ios::binary);
    QuietOpenMesh quiet;
    ok = ext == ".off" ? OpenMesh::IO::IOManager().read(path, importer, options)
                       : OpenMesh::IO::IOManager().read(in, ext.substr(1), importer, options);
  }
  if (!importer.problem.empty())
    throw InputError(where + importer.problem);
  if (!ok)
    throw InputError(where + "not a readable " + ext.substr(1) + " file (truncated or malformed)");
  std::size_t faces_skipped = 0;
  if (census.declared_faces > long(importer.faces.size())) {
    if (ext != ".obj") // a header's count, which the body must meet
      throw InputError(where + "declares " + std::to_string(census.declared_faces) + " faces, but " +
                       std::to_string(importer.faces.size()) + " could be read (truncated or malformed?)");
    faces_skipped = std::size_t(census.declared_faces) - importer.faces.size();
  }
  PolygonSoup soup;
  soup.points.reserve(om.n_vertices());
  for (const auto vh : om.vertices()) {
    const auto& p = om.point(vh);
    soup.points.push_back({p[0], p[1], p[2]});
  }
  if (options.vertex_has_color())
    for (const auto vh : om.vertices()) {
      const auto& c = om.color(vh);
      soup.colours.push_back({c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f});
    }
  if (ext == ".ply") {
    read_ply_labels(om, soup);
    read_ply_arrays(om, soup);
  }
  soup.faces = std::move(importer.faces);
  soup.faces_skipped = faces_skipped;
  return soup;
}

} // namespace

BaseMesh make_base_mesh(std::vector<Vec3> points, const std::vector<std::vector<int>>& faces,
                        const std::string& name, const std::vector<Vec3>& colours)
{
  return build(points, faces, name, name + ": ", colours);
}

PolygonSoup read_mesh_file(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw IOError("cannot open '" + path + "': no such file");
  if (!fs::is_regular_file(path, ec))
    throw IOError("cannot read '" + path + "': not a regular file");
  const std::string ext = lower_extension(path);
  const auto& exts = readable_mesh_extensions();
  if (std::find(exts.begin(), exts.end(), ext) == exts.end())
    throw InputError("cannot read '" + path + "': unknown mesh format '" + ext +
                     "' (readable: .obj .off .ply .stl)");
  if (fs::file_size(path, ec) == 0)
    throw InputError("'" + path + "' is empty");

  const std::string where = "'" + path + "': ";
  if (ext == ".off") {
    try {
      if (!binary_off(path))
        return read_off_text(path);
      PolygonSoup soup;
      if (read_off_binary(path, soup))
        return soup;
    } catch (const InputError& e) {
      throw InputError(where + e.what());
    }
  }
  return read_through_openmesh(path, ext, where);
}

BaseMesh load_mesh(const std::string& path, const ImportOptions& import)
{
  namespace fs = std::filesystem;
  return import_mesh(read_mesh_file(path), fs::path(path).stem().string(), "'" + path + "': ", import);
}

BaseMesh import_mesh(PolygonSoup soup, const std::string& name, const std::string& where,
                     const ImportOptions& import)
{
  const std::size_t faces_skipped = soup.faces_skipped;
  if (soup.faces.empty())
    throw InputError(where + "has no faces");
  // Welding and orienting compute with the coordinates: they must be usable.
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    check_coordinates(soup.points[v], v, where);
  const std::size_t file_vertices = soup.points.size();
  take_channel_arrays(soup, import.arrays, where);
  const SoupSteps steps = import_soup(soup, import.weld);
  if (soup.faces.empty())
    throw InputError(where + "has no faces (every face is degenerate)");
  check_label_ids(soup.labels, where);
  BaseMesh mesh;
  if (steps.oriented_manifold) {
    // Faces that join as they are (checked by import_soup()): OpenMesh's
    // build would change nothing and find no non-manifold vertex to split.
    const auto point = [&](std::size_t v) { return soup.points[v]; };
    const auto faces = [&](const auto& visit) {
      for (const std::vector<int>& f : soup.faces)
        visit(f);
    };
    mesh = assemble(soup.points.size(), point, faces, ImportReport(), name, where, soup.colours, soup.labels,
                    soup.channels, {});
    check_extent(mesh, where);
  } else
    mesh = build(soup.points, soup.faces, name, where, soup.colours, soup.labels, soup.channels);
  mesh.label_classes = soup.label_classes;
  ImportReport& r = mesh.report;
  r.faces_skipped_by_reader = faces_skipped;
  r.degenerate_faces_dropped += steps.degenerate_faces_dropped;
  r.duplicate_faces_dropped += steps.duplicate_faces_dropped;
  r.vertices_welded = steps.vertices_welded;
  r.weld_tolerance = steps.weld_tolerance;
  r.faces_flipped = steps.faces_flipped;
  r.components_turned_outward = steps.components_turned_outward;
  r.nonorientable_components = steps.nonorientable_components;
  r.vertices_cut = steps.vertices_cut;
  r.coloured = !mesh.colours.empty();
  r.colour_array = soup.colour_array;
  for (const ChannelArray& a : mesh.channels)
    r.channel_arrays.emplace_back(a.array, a.channel);
  r.array_vertices = file_vertices;
  r.named_label_classes = mesh.label_classes.size();
  // Id 0 is unlabelled surface: an array of zeros only (meshpaint's own
  // output before any label stroke) brings nothing to import.
  std::set<int> ids(mesh.labels.begin(), mesh.labels.end());
  ids.erase(0);
  if (ids.empty())
    mesh.labels.clear();
  else {
    r.label_array = soup.label_array;
    r.label_classes = ids.size();
  }
  return mesh;
}

PolyMesh to_openmesh(const BaseMesh& base)
{
  PolyMesh mesh;
  mesh.reserve(base.vertex_count(), base.face_vertices.size(), base.face_count());
  for (const Vec3& p : base.points)
    mesh.add_vertex(PolyMesh::Point(p[0], p[1], p[2]));
  std::vector<PolyMesh::VertexHandle> vh;
  for (std::size_t f = 0; f < base.face_count(); ++f) {
    vh.clear();
    for (int k = 0; k < base.face_sizes[f]; ++k)
      vh.emplace_back(base.face_vertices[base.face_offsets[f] + k]);
    mesh.add_face(vh);
  }
  return mesh;
}

} // namespace meshpaint
