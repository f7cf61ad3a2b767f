// What `meshpaint info` reports about a base mesh.
#pragma once

#include "mesh/base_mesh.h"

#include <map> // for std::map

namespace meshpaint {

struct MeshStats
{
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::map<int, std::size_t> faces_by_size;     //!< corners -> faces
  std::size_t components = 0;
  std::size_t boundary_loops = 0, boundary_edges = 0;
  long euler_characteristic = 0;                //!< V - E + F
  long genus = 0;                               //!< summed over components
  std::map<int, std::size_t> valences;          //!< valence -> vertices
  Vec3 bbox_min{}, bbox_max{};
};

//! Counts, components, genus (from the Euler characteristic and boundary
//! loops of each component), boundaries and valences, via OpenMesh.
MeshStats compute_stats(const BaseMesh& mesh);

} // namespace meshpaint
