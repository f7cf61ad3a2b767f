// What one stroke did: its dabs, the patches they touched, its time, and
// with phase timing on where its dabs spent it.
#pragma once

#include <cstddef> // for std::size_t

namespace meshpaint {

//! Where a stroke's dabs spent their time, summed over the dabs, when
//! PaintSurface::time_phases() is on. Each phase ends with a wait for the
//! device, which the phases then pay instead of the next one.
struct StepPhases
{
  double place = 0;     //!< snapping, culling, reach and the flood (brush_patches)
  double record = 0;    //!< the undo snapshot, and a coarse edit's encoding of details
  double weights = 0;   //!< dab_weights, and a coarse edit's edit-level limit; no weights for
                        //!< sculpt, inflate, flatten at any level, which weigh as they move
  double transform = 0; //!< the move (with its weights: move_dab), the smoothing passes or paint_dab
  double rebuild = 0;   //!< a coarse edit: subdivision to the finest level and decoding
  double lists = 0;     //!< the corner neighbourhood and its patch set (host)
  double limit = 0;     //!< limit positions, normals and patch bounds
};

//! What one stroke did.
struct StrokeReport
{
  std::size_t dabs = 0;            //!< dab positions along the stroke (mirrored ones included)
  std::size_t dabs_applied = 0;    //!< those on the surface
  std::size_t patches_touched = 0; //!< summed over dabs
  bool left_surface = false;       //!< the stroke ended where it left the surface
  float stretch = 1.f;             //!< edits at a coarser level: worst growth of a patch's sampling (Multires::stretch)
  double ms = 0;                   //!< wall time, device work included
  double encode_ms = 0;            //!< of which the encoding of details for coarse edits (Multires::encode)
  StepPhases phases;               //!< with PaintSurface::time_phases() on
};

} // namespace meshpaint
