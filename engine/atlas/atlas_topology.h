// Connectivity of the patch atlas: after the first Catmull-Clark step every
// face is a quad, and each quad is one patch. Patch p is level-1 face p.
#pragma once

#include "atlas_types.h" // for PatchEdge, CornerRing, CornerSlot
#include "core/marks.h"

#include <opensubdiv/far/topologyLevel.h> // for Far::TopologyLevel

#include <array>   // for std::array
#include <cstddef> // for std::size_t
#include <vector>  // for std::vector

namespace meshpaint {

struct BaseMesh;

//! The patch tables of the first Catmull-Clark step.
struct AtlasTopology
{
  int patch_count = 0;
  std::vector<std::array<int, 4>> patch_corners; //!< #patches, level-1 vertex per corner
  std::vector<std::array<int, 4>> patch_sides;   //!< #patches, level-1 edge per side
  std::vector<PatchEdge> edges;                  //!< #level-1 edges
  std::vector<CornerRing> rings;                 //!< #level-1 vertices
  std::vector<CornerSlot> slots;                 //!< sum of ring counts

  //! The patch across side `side` of `patch`, or -1 on a mesh boundary.
  int across(int patch, int side) const
  {
    const PatchEdge& e = edges[std::size_t(patch_sides[std::size_t(patch)][std::size_t(side)])];
    return e.patch[0] == patch && e.side[0] == side ? e.patch[1] : e.patch[0];
  }
  //! Vertices of the welded level-l surface (each stored copy counted once).
  std::size_t unique_vertices(int level) const;
  //! `patches` and every patch sharing a corner with one, in patch order,
  //! each once, on the caller's scratch, which a caller doing this often
  //! keeps: afterwards `in` holds the result's patches.
  std::vector<int> corner_neighbourhood(const std::vector<int>& patches, Marks& in, Marks& ring_done) const;
};

//! Builds the tables from OpenSubdiv's level-1 topology.
//! \throw InputError when an edge has more than two faces, the two faces of
//! an edge disagree on orientation, or a vertex's faces form several fans.
AtlasTopology build_atlas_topology(const OpenSubdiv::Far::TopologyLevel& level1);
//! The patch tables of a mesh without a device: one Catmull-Clark step
//! through OpenSubdiv.
//! \throw InputError as build_atlas_topology().
AtlasTopology atlas_topology_of(const BaseMesh& mesh);
//! The peak host memory atlas_topology_of() takes on `mesh` (OpenSubdiv's
//! refined level and the tables), planned before any of it is allocated:
//! linear in the patches, from the bytes per patch measured on a scan of
//! 10^7 triangles, with a margin of 20%.
std::size_t atlas_topology_bytes(const BaseMesh& mesh);

} // namespace meshpaint
