// Coarse edits: details encoded before, the finest level rebuilt after.

#include "paint/coarse_edit.h"

#include "core/timer.h"
#include "paint/paint_memory.h"
#include "paint/reshape.h"

#include <memory> // for std::make_unique

namespace meshpaint {

void CoarseEdits::begin(std::size_t patch_count)
{
  stretched_.clear();
  stretched_marks_.begin(patch_count);
  encode_ms_ = 0;
}

std::vector<int> CoarseEdits::prepare(const DabContext& context, const std::vector<int>& patches, int level,
                                      bool reweigh)
{
  const PaintState& s = context.state;
  if (!s.multires) {
    check_coarse_edits_fit(s.atlas);
    s.multires = std::make_unique<Multires>(s.atlas);
  }
  // Details persist across strokes at the same level; a stroke at the
  // finest level or at another level has them made again. Undo puts back
  // the encoding a step replaced, so a replay of what remains applied
  // encodes exactly where the session did.
  if (s.multires->level() != level) {
    context.hooks.remember_details();
    s.atlas.runtime().queue().finish(); // the encoding timed alone
    const Timer encoding;
    s.multires->encode(level);
    s.atlas.runtime().queue().finish();
    encode_ms_ += encoding.ms();
  }
  // The edit level's limit, which the weights stand on, is computed on
  // the device while the host works out what the edit reaches (and, for
  // the weights, which sides it shares): neither waits for the other.
  context.hooks.phase_done(&StepPhases::record); // the encoding, if any
  if (reweigh) {
    s.multires->compute_base_limit(patches);
    context.hooks.phase_done(&StepPhases::weights);
  }
  return s.multires->reach(patches);
}

void CoarseEdits::rebuild(const DabContext& context, const std::vector<int>& changed)
{
  const PaintState& s = context.state;
  const PatchSet around = s.atlas.neighbourhood(changed);
  context.hooks.phase_done(&StepPhases::lists);
  s.multires->reconstruct(changed, around);
  for (const int p : changed)
    if (stretched_marks_.mark(std::size_t(p)))
      stretched_.push_back(p);
  context.hooks.phase_done(&StepPhases::rebuild);
  refresh_geometry(context, around);
}

float CoarseEdits::stretch(const DabContext& context)
{
  if (stretched_.empty())
    return 1.f;
  context.hooks.phase_start();
  const float worst = context.state.multires->stretch(stretched_);
  context.hooks.phase_done(&StepPhases::rebuild);
  return worst;
}

} // namespace meshpaint
