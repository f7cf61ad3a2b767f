// The patches around one patch laid flat in its texel frame, across their
// shared sides: where parameter-space brushes paint.
#pragma once

#include "atlas/atlas_topology.h"

#include <vector> // for std::vector

namespace meshpaint {

//! The patches a square in the parameters of one patch reaches, and how
//! their texels lie in that patch's frame.
struct Unfolding
{
  //! The centre patch first, then the others laid breadth-first, then those
  //! that only share sides or corners with laid ones.
  std::vector<int> patches;
  std::vector<PatchUnfolding> maps; //!< one per entry of `patches`
};

//! Unfolds the patches around `centre_patch` that the square of half-side
//! `half` (texels) around `centre` (texels of that patch, n per tile side)
//! reaches. Patches are laid breadth-first from the centre patch across
//! their sides, each the first way it is reached while its tile meets the
//! square and the way crosses at most a few sides more than a straight one
//! (so it cannot wind on around irregular vertices to surface far away);
//! around a vertex of valence other than 4 this is one choice of
//! several, and a patch the search does not lay gets only the texels it
//! shares with laid ones. A side or corner texel takes the map of the
//! earliest laid patch that stores it, in every patch that stores it, so all
//! copies agree.
Unfolding unfold(const AtlasTopology& topology, int centre_patch, int n, const float centre[2], float half);

} // namespace meshpaint
