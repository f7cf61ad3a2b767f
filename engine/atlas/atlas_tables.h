// The atlas's connectivity tables on the host (AtlasTopology) and their
// device copies in the form the kernels stream them, as OpenSubdiv keeps
// Far's tables apart from the evaluators that read them.
#pragma once

#include "atlas/atlas_topology.h"
#include "cl/runtime.h"

#include <vector> // for std::vector

namespace meshpaint {

class AtlasTables
{
public:
  //! Uploads the tables of `topology`.
  //! \throw cl::Error when the device cannot take them.
  AtlasTables(Runtime& runtime, AtlasTopology topology);

  const AtlasTopology& topology() const { return topology_; }
  //! Index of level-1 vertex v's ring in the device's ring table.
  int device_ring(int v) const { return device_ring_[std::size_t(v)]; }

  const cl::Buffer& edges() const { return edges_; } //!< PatchEdge per level-1 edge
  //! CornerRing per level-1 vertex, in the order of their first patch.
  const cl::Buffer& rings() const { return rings_; }
  //! CornerSlot, sum of ring counts: a ring's in a row, in the rings' order.
  const cl::Buffer& slots() const { return slots_; }
  //! limit_corners' constants: two float4 per valence up to the largest
  //! (interior, boundary).
  const cl::Buffer& valences() const { return valences_; }
  //! For whole-tile kernels (border_entry() in atlas_access.cl), int4 per
  //! patch: each side's edge as 2 * edge + (1 where the patch is the edge's
  //! second), and each corner's ring in the device's ring table.
  const cl::Buffer& patch_sides() const { return patch_sides_; }
  const cl::Buffer& patch_rings() const { return patch_rings_; }
  //! int4 per patch: across each side, 4 * patch + its side there; -1 on a
  //! mesh boundary.
  const cl::Buffer& patch_across() const { return patch_across_; }
  //! int4 per patch: where each of its corners sits in slots().
  const cl::Buffer& patch_slots() const { return patch_slots_; }

private:
  AtlasTopology topology_;
  std::vector<int> device_ring_; // level-1 vertex -> index in the device's ring table
  cl::Buffer edges_, rings_, slots_, valences_, patch_sides_, patch_rings_, patch_across_, patch_slots_;
};

} // namespace meshpaint
