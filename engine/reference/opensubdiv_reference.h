// OpenSubdiv's answers for a mesh: the oracle that the atlas kernels are
// tested against, and the peer they are benchmarked against.
#pragma once

#include "atlas/atlas_topology.h"
#include "mesh/base_mesh.h"

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

namespace meshpaint {

//! Level-l points by Far::PrimvarRefiner, in OpenSubdiv's vertex order; with
//! `limit`, also PrimvarRefiner::Limit positions and unit normals (du x dv).
struct ReferenceLevel
{
  std::vector<Vec3> points;
  std::vector<Vec3> limit_points;
  std::vector<Vec3> limit_normals;
};
ReferenceLevel opensubdiv_level(const BaseMesh& mesh, int level, bool limit);

//! For each welded vertex of the atlas's level (weld_map order), the index of
//! the same vertex in OpenSubdiv's level, found through Far's parent-child
//! relations, not through positions.
//! \throw std::logic_error when the atlas and Far disagree on topology.
std::vector<int> opensubdiv_vertex_order(const BaseMesh& mesh, const AtlasTopology& topology, int level);

//! Far::StencilTable + Osd::CpuEvaluator from the base mesh to one level.
class StencilPeer
{
public:
  StencilPeer(const BaseMesh& mesh, int level);
  ~StencilPeer();
  //! Evaluates every level-l vertex from the base mesh's points.
  void evaluate();
  double build_ms() const { return build_ms_; }
  std::size_t vertices() const;
  std::size_t stencil_weights() const;
  //! Bytes one evaluation must move at least: the stencil tables, the
  //! gathered base points and the written level.
  std::size_t bytes_moved() const;
  std::vector<Vec3> result() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double build_ms_ = 0;
};

} // namespace meshpaint
