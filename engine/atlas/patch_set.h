// "These patches" in one type: a set of patches with the sides and corners
// that go with them, as every patch, as host lists, or as device flags; and
// the host lists' maker.
#pragma once

#include "atlas/atlas_tables.h"
#include "cl/opencl.h"
#include "core/marks.h"

#include <cstdint> // for std::uint8_t
#include <vector>  // for std::vector

namespace meshpaint {

//! Whether an edge or ring goes with a set of patches when any of its
//! patches is in the set, or only when all are.
enum class Reach
{
  Any,
  All
};

//! Some patches with the patch edges and corner rings that go with them, as
//! the kernels that take a subset take them.
struct PatchSet
{
  enum class Form
  {
    All,   //!< every patch, edge and ring; the lists are empty
    Lists, //!< the lists below
    Flags  //!< the items whose device flag holds `generation` (select.cl)
  };
  Form form = Form::All;

  // Form::Lists.
  std::vector<int> patches; //!< sorted
  std::vector<int> edges;   //!< indices into AtlasTopology::edges
  std::vector<int> rings;   //!< indices into the device's ring table
  std::vector<int> corners; //!< the level-1 vertex of each ring
  //! Reach::All only: per patch, the sides (bits 0-3) and corners (bits
  //! 4-7) it shares with a patch outside the set (texel_border()'s bits).
  std::vector<std::uint8_t> outside;
  //! The three lists on the device where uploaded already; null: uploaded
  //! by each call that takes the set.
  cl::Buffer patch_list, edge_list, ring_list;

  // Form::Flags: valid until the atlas makes its next flags.
  cl::Buffer patch_flags, edge_flags, ring_flags;
  int generation = 0;
};

//! Makes PatchSets' host lists on an atlas's tables. Its scratch stays
//! between calls, since a brush step calls it on most of the atlas: a call
//! costs only what it visits (and calls on one maker must not overlap).
class PatchSetMaker
{
public:
  explicit PatchSetMaker(const AtlasTables& tables) : tables_(tables) {}

  //! The edges and rings that go with `patches` by `reach`.
  PatchSet lists(const std::vector<int>& patches, Reach reach);
  //! `patches` and every patch sharing a corner with one, in patch order,
  //! each once (AtlasTopology::corner_neighbourhood() on this scratch).
  std::vector<int> corner_neighbourhood(const std::vector<int>& patches);
  //! `changed` and every patch sharing a corner with one (each holds copies
  //! of moved texels' limit), by Reach::Any.
  PatchSet neighbourhood(const std::vector<int>& changed);
  //! Per patch of `patches`, the sides (bits 0-3) and corners (bits 4-7) it
  //! shares with a patch not listed (as PatchSet::outside).
  std::vector<std::uint8_t> shared_outside(const std::vector<int>& patches);

private:
  //! The set of `patches` (in patch order, and the ones patch_marks_ holds).
  PatchSet marked_set(std::vector<int> patches, Reach reach);
  //! PatchSet::outside of each of `patches` (each once), the set being what
  //! patch_marks_ holds.
  std::vector<std::uint8_t> outside_of(const std::vector<int>& patches);

  const AtlasTables& tables_;
  Marks patch_marks_, edge_marks_, ring_marks_, ring_seen_;
  std::vector<int> ring_held_; // outside_of(): per ring, its slots held by the set's patches
};

} // namespace meshpaint
