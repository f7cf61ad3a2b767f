// The base mesh as an OpenSubdiv topology refiner: the Catmull-Clark rules
// the atlas follows (boundary: VTX_BOUNDARY_EDGE_AND_CORNER).
#pragma once

#include "mesh/base_mesh.h"

#include <opensubdiv/far/topologyRefiner.h> // for Far::TopologyRefiner

#include <memory> // for std::unique_ptr

namespace meshpaint {

namespace Far = OpenSubdiv::Far;

//! Unrefined refiner over the base mesh's topology.
//! \throw InputError when OpenSubdiv rejects the topology.
std::unique_ptr<Far::TopologyRefiner> make_refiner(const BaseMesh& mesh);

//! Refines uniformly to `level`; `full_topology` keeps the last level's
//! complete topology, which PrimvarRefiner::Limit needs.
void refine_uniform(Far::TopologyRefiner& refiner, int level, bool full_topology);

//! Positions of every level up to the refiner's last, level 0 first.
std::vector<std::vector<Vec3>> interpolate_levels(const Far::TopologyRefiner& refiner,
                                                  const std::vector<Vec3>& base);

} // namespace meshpaint
