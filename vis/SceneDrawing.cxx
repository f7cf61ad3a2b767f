#include "SceneDrawing.h"

#include "LevelOfDetail.h"     // for meshpaint::coarser_quads
#include "SharedArrays.h"      // for meshpaint::share_arrays, refresh_shared_arrays
#include "SurfaceConversion.h" // for meshpaint::to_polydata, update_polydata

#include "paint/paint_surface.h" // for meshpaint::PaintSurface

namespace meshpaint {

vtkPolyData* drawn_surface(ObjectDrawing& d, PaintSurface& surface, int level, int painting_level, bool share)
{
  if (!d.full) {
    d.full_count = surface.change_count();
    d.full = to_polydata(surface.painted_surface());
    d.coarse = nullptr;
    // Where the device's memory is the host's, the arrays drawn are the
    // engine's own: a kernel writes the patches that change, in place.
    const auto shared = share ? surface.display_arrays() : nullptr;
    if (shared) {
      share_arrays(d.full, shared);
      d.seen.clear();
      for (std::size_t k = 0; k < shared->arrays().size(); ++k)
        d.seen.push_back(shared->version(k));
    }
    d.shared = shared != nullptr;
  } else if (d.full_stale) {
    // Same topology: only the vertices of the patches that changed are
    // written (on the device into the shared arrays, else read back into
    // VTK's), and only the arrays that changed are marked (and uploaded).
    const PatchChanges changes = surface.changes_since(d.full_count);
    d.full_count = surface.change_count();
    const auto shared = d.shared ? surface.display_arrays() : nullptr; // brought up to date
    if (shared) {
      if (refresh_shared_arrays(d.full, shared, d.seen))
        d.coarse = nullptr; // it shares the arrays that moved
    } else if (changes.all) {
      update_polydata(d.full, surface.painted_surface());
    } else {
      update_polydata(d.full, surface.painted_vertices(changes.patches));
    }
  }
  d.full_stale = false;
  if (level == painting_level)
    return d.full;
  // A coarser tessellation of the same painted surface, sharing its points
  // and arrays; the atlas is not touched (a reduction there would start
  // multiresolution edits afresh).
  if (!d.coarse || d.coarse_level != level) {
    const int n = 1 << (painting_level - 1), stride = 1 << (painting_level - level);
    d.coarse = coarser_quads(d.full, n, stride);
    d.coarse_level = level;
  }
  return d.coarse;
}

} // namespace meshpaint
