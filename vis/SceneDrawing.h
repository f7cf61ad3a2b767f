// What the painting window draws of each object: the painted surface at
// the painting level, brought up to date patch by patch after strokes, and
// its coarser tessellations for the level of detail.
#ifndef SceneDrawing_h
#define SceneDrawing_h

#include <vtkActor.h>        // for vtkActor
#include <vtkNew.h>          // for vtkNew
#include <vtkPolyData.h>     // for vtkPolyData
#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <cstdint> // for std::uint64_t
#include <vector>  // for std::vector

namespace meshpaint {

class PaintSurface;

//! One object of the scene as drawn: its painted surface at the painting
//! level, brought up to date when next drawn after a change, its coarser
//! tessellation for the level of detail (made once per level, sharing the
//! arrays), and its actor, which draws `shown`.
struct ObjectDrawing
{
  vtkSmartPointer<vtkPolyData> full, coarse, shown;
  bool full_stale = true;
  std::uint64_t full_count = 0;    //!< the surface's change_count() that `full` shows
  bool shared = false;             //!< `full` draws from the engine's display arrays
  std::vector<std::uint64_t> seen; //!< their versions `full` was last marked for
  int coarse_level = 0;
  vtkNew<vtkActor> actor;
};

//! `drawing`'s surface of `surface` at `level` (`painting_level`, or a
//! coarser level of detail), rebuilt if stale: only the vertices of the
//! patches that changed are written, and only the arrays that changed are
//! marked modified. `share`: a first build draws from the engine's display
//! arrays where the device's memory is the host's.
//! \throw DeviceError when reading back from the device fails.
vtkPolyData* drawn_surface(ObjectDrawing& drawing, PaintSurface& surface, int level, int painting_level, bool share);

} // namespace meshpaint

#endif
