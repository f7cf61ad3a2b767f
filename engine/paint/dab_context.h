// What a tool family's dab works with besides the surface's PaintState: the
// side of a two-sided surface it paints, whether a mask was painted, and the
// running stroke's hooks (remember tiles for undo before they change, time
// the phases). The surface that owns the stroke implements the hooks.
#pragma once

#include "cl/opencl.h"
#include "paint/paint_state.h"
#include "paint/stroke.h"
#include "paint/stroke_report.h"

#include <functional> // for std::function
#include <vector>     // for std::vector

namespace meshpaint {

//! The running stroke, as the tool families see it.
class StrokeHooks
{
public:
  //! Before `patches` change: their tiles into the stroke's undo step (once
  //! per stroke), and a change recorded for them.
  virtual void remember(const std::vector<int>& patches) = 0;
  //! Before the multiresolution details are encoded at another level: the
  //! undo step keeps the encoding it replaces.
  virtual void remember_details() = 0;
  //! With phase timing on: waits for the device and starts the clock
  //! (phase_start), or adds the time since to `phase` (phase_done).
  virtual void phase_start() = 0;
  virtual void phase_done(double StepPhases::*phase) = 0;

protected:
  ~StrokeHooks() = default;
};

//! One dab's surroundings: the surface's state, the running stroke's hooks,
//! and two flags of the surface, by reference.
struct DabContext
{
  PaintState state;
  StrokeHooks& hooks;
  //! The running dab paints the inside of a two-sided surface.
  bool& inside;
  //! A mask may be set somewhere (else the weights skip reading it).
  bool& mask_painted;

  //! The channel buffers a dab writes: those of the side it paints.
  cl::Buffer& diffuse() const;
  cl::Buffer& specular() const;
  cl::Buffer& material() const;
};

//! Places a dab at `sample` for `stroke` (the surface's placement and side):
//! the patches it may change, empty where it misses; sets `normal`.
using PlaceDab = std::function<std::vector<int>(const Stroke& stroke, const DabSample& sample, BrushDab& dab,
                                                Vec3& normal)>;

} // namespace meshpaint
