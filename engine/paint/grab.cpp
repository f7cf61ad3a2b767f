// The grab tool's region, taken and pulled.

#include "paint/grab.h"

#include "paint/reshape.h"

namespace meshpaint {

bool GrabRegion::step(const DabContext& context, CoarseEdits& coarse, const Stroke& stroke, BrushDab& dab,
                      const std::vector<DabSample>& samples, std::size_t index, bool mine, const PlaceDab& place,
                      StrokeReport& report)
{
  if (index > 0) {
    if (held_)
      pull(context, coarse, stroke, dab, samples[index].centre, report);
    return true;
  }
  held_ = false;
  if (!mine)
    return true;
  dab.radius = stroke.brush.radius * samples.front().pressure;
  dab.strength = stroke.brush.strength * samples.front().pressure;
  if (!(dab.radius > 0.f))
    return true;
  Vec3 normal;
  context.hooks.phase_start();
  patches_ = place(stroke, samples.front(), dab, normal);
  context.hooks.phase_done(&StepPhases::place);
  if (patches_.empty())
    return false;
  held_ = true;
  at_ = samples.front().centre;
  return true;
}

void GrabRegion::end(const DabContext& context, CoarseEdits& coarse, const Stroke& stroke, const BrushDab& dab,
                     StrokeReport& report)
{
  const std::vector<DabSample> samples = stroke_samples(stroke);
  const bool last = stroke.points.size() > 1 && samples.back().centre != stroke.points.back();
  report.dabs = samples.size() + (last ? 1 : 0);
  if (last && held_)
    pull(context, coarse, stroke, dab, stroke.points.back(), report);
}

void GrabRegion::pull(const DabContext& context, CoarseEdits& coarse, const Stroke& stroke, const BrushDab& dab,
                      const Vec3& to, StrokeReport& report)
{
  reshape_dab(context, coarse, patches_, dab, stroke, sub(to, at_), moves_ == 0);
  ++moves_;
  at_ = to;
  ++report.dabs_applied;
  report.patches_touched += patches_.size();
}

} // namespace meshpaint
