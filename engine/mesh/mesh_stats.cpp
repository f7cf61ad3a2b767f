#include "mesh/mesh_stats.h"

#include "mesh/openmesh_types.h"

#include <algorithm> // for std::min, std::max
#include <vector>    // for std::vector

namespace meshpaint {

MeshStats compute_stats(const BaseMesh& base)
{
  PolyMesh mesh = to_openmesh(base); // circulators need a mutable mesh

  MeshStats s;
  s.vertices = mesh.n_vertices();
  s.edges = mesh.n_edges();
  s.faces = mesh.n_faces();
  s.euler_characteristic = long(s.vertices) - long(s.edges) + long(s.faces);
  for (const auto fh : mesh.faces())
    ++s.faces_by_size[int(mesh.valence(fh))];
  s.bbox_min = s.bbox_max = base.points.front();
  for (const auto vh : mesh.vertices()) {
    ++s.valences[int(mesh.valence(vh))];
    const auto& p = mesh.point(vh);
    for (int a = 0; a < 3; ++a) {
      s.bbox_min[a] = std::min(s.bbox_min[a], p[a]);
      s.bbox_max[a] = std::max(s.bbox_max[a], p[a]);
    }
  }

  // Components by flood fill over vertices; per component V, E, F, loops.
  std::vector<int> comp(mesh.n_vertices(), -1);
  std::vector<long> chi;
  std::vector<long> loops;
  for (const auto seed : mesh.vertices()) {
    if (comp[seed.idx()] >= 0)
      continue;
    const int c = int(chi.size());
    chi.push_back(0);
    loops.push_back(0);
    std::vector<PolyMesh::VertexHandle> stack{seed};
    comp[seed.idx()] = c;
    while (!stack.empty()) {
      const auto v = stack.back();
      stack.pop_back();
      for (const auto w : mesh.vv_range(v))
        if (comp[w.idx()] < 0) {
          comp[w.idx()] = c;
          stack.push_back(w);
        }
    }
  }
  for (const auto vh : mesh.vertices())
    chi[comp[vh.idx()]] += 1;
  for (const auto eh : mesh.edges())
    chi[comp[mesh.from_vertex_handle(mesh.halfedge_handle(eh, 0)).idx()]] -= 1;
  for (const auto fh : mesh.faces())
    chi[comp[mesh.fv_begin(fh)->idx()]] += 1;

  std::vector<char> seen(mesh.n_halfedges(), 0);
  for (const auto he : mesh.halfedges()) {
    if (!mesh.is_boundary(he) || seen[he.idx()])
      continue;
    ++s.boundary_loops;
    ++loops[comp[mesh.from_vertex_handle(he).idx()]];
    for (auto h = he; !seen[h.idx()]; h = mesh.next_halfedge_handle(h)) {
      seen[h.idx()] = 1;
      ++s.boundary_edges;
    }
  }
  s.components = chi.size();
  for (std::size_t c = 0; c < chi.size(); ++c)
    s.genus += (2 - chi[c] - loops[c]) / 2;
  return s;
}

} // namespace meshpaint
