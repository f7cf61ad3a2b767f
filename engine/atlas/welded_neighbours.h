// The atlas's level as the umbrella operator sees it: the welded quad mesh
// (weld.h) with each vertex's neighbours, so that smoothing passes read a
// compact array instead of gathering across patch tiles.
#pragma once

#include "atlas/atlas_topology.h"
#include "atlas/patch_layout.h"

#include <array>  // for std::array
#include <vector> // for std::vector

namespace meshpaint {

//! How weld_map() numbers a level's vertices: corners (one per level-1
//! vertex), then the side texels edge by edge, then the patch interiors.
struct WeldedNumbering
{
  int inner = 0;         //!< texels along a side between its corners (n - 1)
  int edge_base = 0;     //!< first side-texel vertex (vertices before it are corners)
  int interior_base = 0; //!< first patch-interior vertex

  //! The vertices that smoothing moves on a patch set taken with Reach::All:
  //! the interiors of `patches`, the side texels of `edges` and the corners
  //! `corners` (level-1 vertices).
  std::vector<int> moved(const std::vector<int>& patches, const std::vector<int>& edges,
                         const std::vector<int>& corners) const;
  std::size_t moved_count(std::size_t patches, std::size_t edges, std::size_t corners) const
  {
    return corners + edges * std::size_t(inner) + patches * std::size_t(inner) * std::size_t(inner);
  }
};

//! The numbering with the tables smoothing reads.
struct WeldedNeighbours : WeldedNumbering
{
  std::vector<int> vertex_of;   //!< per texel (patch-major), as weld_map()
  std::vector<int> texel;       //!< per vertex: the texel its weight is read from
  std::vector<int> first;       //!< per corner, and one more: where its ring starts in `ring`
  std::vector<int> ring;        //!< corners' neighbours, in ring order
  std::vector<std::array<int, 4>> around; //!< per vertex from edge_base on: summed in pairs

  std::size_t vertices() const { return texel.size(); }
};

//! Neighbours of every welded vertex of the level: 4 inside a patch and
//! along a shared side; along a mesh-boundary side its two on the side, each
//! twice; at a corner the ring's in order, or the two boundary neighbours at
//! a boundary corner, or none at the corner of a single face (which stays
//! where it is).
WeldedNeighbours welded_neighbours(const AtlasTopology& topology, const LevelLayout& layout);

} // namespace meshpaint
