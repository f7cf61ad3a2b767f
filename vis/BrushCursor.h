// Picking in the painting window and the ring that shows the brush there:
// the surface point under a pixel, found in vtkSurfacePicker's item buffer,
// which is captured again only when the camera or the window size changed.
#ifndef BrushCursor_h
#define BrushCursor_h

#include "vtkSurfacePicker.h" // for vtkSurfacePicker

#include <vtkActor.h>                // for vtkActor
#include <vtkNew.h>                  // for vtkNew
#include <vtkRegularPolygonSource.h> // for vtkRegularPolygonSource

#include <array> // for std::array

class vtkRenderer;
class vtkRenderWindow;

namespace meshpaint {

class BrushCursor
{
public:
  //! Adds the ring (hidden, not pickable) to `renderer`.
  void add_to(vtkRenderer* renderer);
  vtkSurfacePicker* picker() { return picker_; }
  //! The surface at display pixel (x, y) of `window` when it faces the
  //! viewer with a cosine of at least `min_facing`, on either side (faces
  //! wound inwards or outwards): its point and its normal turned to the viewer.
  bool pick_facing(vtkRenderer* renderer, vtkRenderWindow* window, int x, int y, double min_facing,
                   double point[3], double normal[3]);
  //! Shows a ring of `radius` at `point`, just above the surface along
  //! `normal` (on), or hides it.
  void place(bool on, const double point[3], const double normal[3], double radius);
  bool visible() const { return ring_->GetVisibility() != 0; }

private:
  vtkNew<vtkSurfacePicker> picker_;
  // The item buffer holds for one view: camera pose and window size (the
  // camera's modification time also moves with every clipping-range reset).
  std::array<double, 13> captured_view_{};
  vtkNew<vtkRegularPolygonSource> shape_;
  vtkNew<vtkActor> ring_;
};

} // namespace meshpaint

#endif
