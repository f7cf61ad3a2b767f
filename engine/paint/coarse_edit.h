// Coarse edits: geometry brushes at a coarser edit level move that level's
// control points, and the finer levels are rebuilt from their details
// (Multires, multiresolution editing). What a stroke of them rebuilt is
// kept for its stretch warning.
#pragma once

#include "core/marks.h"
#include "paint/dab_context.h"

#include <cstddef> // for std::size_t
#include <vector>  // for std::vector

namespace meshpaint {

class CoarseEdits
{
public:
  //! A new stroke on a surface of `patch_count` patches: nothing rebuilt yet.
  void begin(std::size_t patch_count);
  //! Before a dab at `level`, coarser than the painting level: the details
  //! encoded for that level (made on first use; they persist across strokes
  //! at the same level, and StrokeHooks::remember_details() comes before an
  //! encoding replaces them), and with `reweigh` the level's limit under
  //! `patches`, which the weights stand on. Returns the finest patches the
  //! edit may change, which are more than the brush's.
  std::vector<int> prepare(const DabContext& context, const std::vector<int>& patches, int level, bool reweigh);
  //! After the edit level's control points moved: the finest level rebuilt
  //! with its details on `changed`, and the limit surface there.
  void rebuild(const DabContext& context, const std::vector<int>& changed);
  //! Multires::stretch of what the stroke rebuilt (1 when nothing), once at
  //! its end: what the edit leaves is what the warning is about.
  float stretch(const DabContext& context);
  //! The stroke's time spent encoding details (Multires::encode), in ms.
  double encode_ms() const { return encode_ms_; }

private:
  std::vector<int> stretched_; // patches the stroke rebuilt from a coarser level
  Marks stretched_marks_;      // per patch: in stretched_
  double encode_ms_ = 0;
};

} // namespace meshpaint
