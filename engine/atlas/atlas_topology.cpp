#include "atlas/atlas_topology.h"

#include "core/errors.h"
#include "mesh/far_refiner.h"

#include <string> // for std::to_string

namespace meshpaint {
namespace {

// Measured: `meshpaint info` on the scan of 10,106,208 triangles of `bench
// fit` (30,318,624 patches) peaks this much higher per patch with the atlas
// topology than without it.
constexpr double kAtlasTopologyBytesPerPatch = 321;
constexpr double kAtlasTopologyMargin = 1.2;

} // namespace

std::size_t AtlasTopology::unique_vertices(int level) const
{
  const std::size_t n = std::size_t(1) << (level - 1), inner = n - 1;
  return rings.size() + edges.size() * inner + std::size_t(patch_count) * inner * inner;
}

AtlasTopology build_atlas_topology(const OpenSubdiv::Far::TopologyLevel& level1)
{
  AtlasTopology topo;
  topo.patch_count = level1.GetNumFaces();
  topo.patch_corners.resize(topo.patch_count);
  topo.patch_sides.resize(topo.patch_count);
  for (int f = 0; f < topo.patch_count; ++f) {
    const auto fv = level1.GetFaceVertices(f);
    const auto fe = level1.GetFaceEdges(f);
    if (fv.size() != 4)
      throw InputError("level-1 face " + std::to_string(f) + " is not a quad");
    for (int k = 0; k < 4; ++k) {
      topo.patch_corners[f][k] = fv[k];
      topo.patch_sides[f][k] = fe[k];
    }
  }

  const int edge_count = level1.GetNumEdges();
  topo.edges.resize(edge_count);
  for (int e = 0; e < edge_count; ++e) {
    const auto faces = level1.GetEdgeFaces(e);
    const auto local = level1.GetEdgeFaceLocalIndices(e);
    if (faces.size() < 1 || faces.size() > 2)
      throw InputError("edge between vertices " + std::to_string(level1.GetEdgeVertices(e)[0]) +
                       " and " + std::to_string(level1.GetEdgeVertices(e)[1]) + " of the first "
                       "subdivision has " + std::to_string(faces.size()) + " faces");
    PatchEdge& pe = topo.edges[e];
    pe.patch[0] = faces[0];
    pe.side[0] = local[0];
    pe.patch[1] = faces.size() == 2 ? faces[1] : -1;
    pe.side[1] = faces.size() == 2 ? local[1] : -1;
    if (faces.size() == 2) {
      // Consistent orientation: the second face runs the edge backwards.
      const auto& c0 = topo.patch_corners[pe.patch[0]];
      const auto& c1 = topo.patch_corners[pe.patch[1]];
      if (c0[pe.side[0]] != c1[(pe.side[1] + 1) % 4] || c0[(pe.side[0] + 1) % 4] != c1[pe.side[1]])
        throw InputError("faces " + std::to_string(pe.patch[0]) + " and " +
                         std::to_string(pe.patch[1]) +
                         " of the first subdivision are oriented inconsistently");
    }
  }

  // Rings: walk from each patch across its incoming side to the next one.
  const int vertex_count = level1.GetNumVertices();
  topo.rings.resize(vertex_count);
  for (int v = 0; v < vertex_count; ++v) {
    const auto faces = level1.GetVertexFaces(v);
    const auto corners = level1.GetVertexFaceLocalIndices(v);
    if (faces.size() == 0)
      throw InputError("vertex " + std::to_string(v) + " of the first subdivision has no face");
    int start = 0;
    bool boundary = false;
    for (int k = 0; k < faces.size(); ++k)
      if (topo.edges[topo.patch_sides[faces[k]][corners[k]]].patch[1] < 0) {
        start = k;
        boundary = true;
      }
    CornerRing& ring = topo.rings[v];
    ring.first = int(topo.slots.size());
    ring.boundary = boundary ? 1 : 0;
    ring.pad = 0;
    int patch = faces[start], corner = corners[start];
    for (int guard = 0; guard <= faces.size(); ++guard) {
      topo.slots.push_back({patch, corner});
      const PatchEdge& in = topo.edges[topo.patch_sides[patch][(corner + 3) % 4]];
      if (in.patch[1] < 0)
        break; // reached the other boundary side
      const int which = in.patch[0] == patch && in.side[0] == (corner + 3) % 4 ? 1 : 0;
      patch = in.patch[which];
      corner = in.side[which];
      if (patch == faces[start] && corner == corners[start])
        break; // closed the ring
    }
    ring.count = int(topo.slots.size()) - ring.first;
    if (ring.count != faces.size())
      throw InputError("vertex " + std::to_string(v) +
                       " of the first subdivision joins several surface sheets (non-manifold)");
  }
  return topo;
}

std::vector<int> AtlasTopology::corner_neighbourhood(const std::vector<int>& patches, Marks& in,
                                                     Marks& ring_done) const
{
  in.begin(std::size_t(patch_count));
  ring_done.begin(rings.size());
  if (patches.size() * 8 > std::size_t(patch_count)) {
    // Many patches: their corners marked, then every patch tested at its
    // four corners in patch order. The patches are along the surface, so
    // the tests' outcomes come in runs, and the scan reads the corner
    // table in order where walking the rings would gather from it; it
    // costs about what the walk does at an eighth of the patches.
    for (const int p : patches)
      for (const int v : patch_corners[std::size_t(p)])
        ring_done.mark(std::size_t(v));
    std::vector<int> out;
    out.reserve(patches.size() + patches.size() / 4);
    for (int q = 0; q < patch_count; ++q) {
      const std::array<int, 4>& c = patch_corners[std::size_t(q)];
      if (ring_done.marked(std::size_t(c[0])) | ring_done.marked(std::size_t(c[1])) |
          ring_done.marked(std::size_t(c[2])) | ring_done.marked(std::size_t(c[3]))) {
        in.mark(std::size_t(q));
        out.push_back(q);
      }
    }
    return out;
  }
  std::vector<int> out;
  out.reserve(2 * patches.size());
  for (const int p : patches)
    if (in.mark(std::size_t(p)))
      out.push_back(p);
  const std::size_t listed = out.size();
  for (std::size_t k = 0; k < listed; ++k)
    for (const int v : patch_corners[std::size_t(out[k])]) {
      if (!ring_done.mark(std::size_t(v)))
        continue; // each corner ring once, not once per patch at it
      const CornerRing& ring = rings[std::size_t(v)];
      for (int m = 0; m < ring.count; ++m) {
        const int q = slots[std::size_t(ring.first + m)].patch;
        if (in.mark(std::size_t(q)))
          out.push_back(q);
      }
    }
  return marked_in_order(std::move(out), in, std::size_t(patch_count));
}

std::size_t atlas_topology_bytes(const BaseMesh& mesh)
{
  // One patch per face corner.
  return std::size_t(kAtlasTopologyMargin * kAtlasTopologyBytesPerPatch * double(mesh.face_vertices.size()));
}

AtlasTopology atlas_topology_of(const BaseMesh& mesh)
{
  auto refiner = make_refiner(mesh);
  refine_uniform(*refiner, 1, true);
  return build_atlas_topology(refiner->GetLevel(1));
}

} // namespace meshpaint
