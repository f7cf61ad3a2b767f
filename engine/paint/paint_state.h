// What the tool families of the brush pipeline work on: a painting surface's
// atlas at its painting level and its device state (channel layers, scratch
// buffers, kernels). PaintSurface owns these and hands them out as a
// PaintState; the families are free functions or small classes over it,
// each in a file named for it (subsurface_light.h, label_edits.h,
// snapshots.h, brush_placement.h; the brushes over a DabContext built on it:
// colour_paint.h, smoothing.h, sculpt.h, grab.h, coarse_edit.h, reshape.h).
#pragma once

#include "atlas/atlas.h"
#include "atlas/multires.h"

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

namespace meshpaint {

struct PaintDevice; // paint_device.h: for the pipeline's own files only

struct PaintState
{
  Atlas& atlas;
  int level; //!< the painting level
  PaintDevice& device;
  //! Per texel of the painting level: its welded vertex; empty until
  //! texel_vertices() first needs it.
  std::vector<int>& weld_map;
  //! Details for edits at a coarser level; null until such an edit needs them.
  std::unique_ptr<Multires>& multires;

  LevelLayout layout() const { return atlas.layout(level); }
};

//! Per texel of the painting level: its welded vertex (weld_map), made once.
const std::vector<int>& texel_vertices(const PaintState& state);

} // namespace meshpaint
