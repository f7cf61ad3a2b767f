// The way of a geometry or colour-filter dab through its steps, timed by
// phase.

#include "paint/reshape.h"

#include "paint/paint_device.h"
#include "paint/sculpt.h"
#include "paint/smoothing.h"

namespace meshpaint {

void reshape_dab(const DabContext& context, CoarseEdits& coarse, const std::vector<int>& patches, const BrushDab& dab,
                 const Stroke& stroke, const Vec3& towards, bool reweigh)
{
  // At a coarser edit level the brush moves that level's control points and
  // the finest level is rebuilt with its details (Multires); the finest
  // patches that may change are then more than the brush's.
  const PaintState& s = context.state;
  const int level = stroke.edit_level() > 0 ? stroke.edit_level() : s.level;
  const bool at_coarse = level < s.level;
  std::vector<int> changed;
  if (at_coarse)
    changed = coarse.prepare(context, patches, level, reweigh);
  else if (tool_family(stroke) != ToolFamily::ColourFilter && s.multires)
    s.multires->detach();
  context.hooks.remember(at_coarse ? changed : patches);
  context.hooks.phase_done(&StepPhases::record);
  const cl::Buffer list = device_ints(s.atlas.runtime().context(), patches);
  const bool moves = tool_family(stroke) == ToolFamily::Move;
  // A move weighs as it moves (move_dab), at any level; the weights are
  // kept only where something reads them again: a grab's later dabs and
  // smoothing passes.
  const bool weigh_as_moved = moves && stroke.tool != Tool::Grab;
  if (reweigh && !weigh_as_moved)
    weigh_dab(context, patches, list, dab, level);
  context.hooks.phase_done(&StepPhases::weights);
  const cl::Buffer& weights = at_coarse ? s.multires->base_weights() : s.device.weights;
  if (moves)
    move_dab(context, patches, list, dab, stroke, towards, level, weigh_as_moved, weights);
  else
    smooth_dab(context, patches, stroke.smooth(), level, weights);
  context.hooks.phase_done(&StepPhases::transform);
  if (!moves && stroke.smooth().target_colour)
    s.atlas.runtime().queue().finish();
  else if (at_coarse)
    coarse.rebuild(context, changed);
  else
    refresh_geometry(context, patches, &list);
}

void refresh_geometry(const DabContext& context, const std::vector<int>& patches, const cl::Buffer* list)
{
  // The limit changed on the patches' sides and corners too, which every
  // patch sharing a corner with them stores: their tiles and bounds as well
  // (Atlas::neighbourhood(); with many patches made on the device).
  const PatchSet set = context.state.atlas.neighbourhood(patches, list);
  context.hooks.phase_done(&StepPhases::lists);
  refresh_geometry(context, set);
}

void refresh_geometry(const DabContext& context, const PatchSet& set)
{
  context.state.atlas.update_limit(set); // and the patches' bounds
  context.hooks.phase_done(&StepPhases::limit);
}

} // namespace meshpaint
