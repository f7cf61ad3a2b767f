#include "BrushCursor.h"

#include <vtkCamera.h>         // for vtkCamera
#include <vtkPolyDataMapper.h> // for vtkPolyDataMapper
#include <vtkProperty.h>       // for vtkProperty
#include <vtkRenderWindow.h>   // for vtkRenderWindow
#include <vtkRenderer.h>       // for vtkRenderer

#include <cmath> // for std::fabs

namespace meshpaint {

void BrushCursor::add_to(vtkRenderer* renderer)
{
  shape_->SetNumberOfSides(40);
  shape_->GeneratePolygonOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(shape_->GetOutputPort());
  ring_->SetMapper(mapper);
  ring_->GetProperty()->SetColor(1.0, 0.85, 0.2);
  ring_->GetProperty()->LightingOff();
  ring_->GetProperty()->SetLineWidth(2.0);
  ring_->PickableOff(); // the item buffer must see the surface through it
  ring_->VisibilityOff();
  renderer->AddActor(ring_);
}

bool BrushCursor::pick_facing(vtkRenderer* renderer, vtkRenderWindow* window, int x, int y, double min_facing,
                              double point[3], double normal[3])
{
  vtkCamera* camera = renderer->GetActiveCamera();
  const int* size = window->GetSize();
  std::array<double, 13> view;
  camera->GetPosition(&view[0]);
  camera->GetFocalPoint(&view[3]);
  camera->GetViewUp(&view[6]);
  view[9] = camera->GetViewAngle();
  view[10] = camera->GetParallelProjection() ? camera->GetParallelScale() : 0.0;
  view[11] = size[0];
  view[12] = size[1];
  if (!picker_->IsCaptured() || view != captured_view_) {
    picker_->Capture();
    captured_view_ = view;
  }
  // Scans come wound either way: whichever side of the surface the eye
  // sees is the one under the cursor, and its normal is turned towards it.
  if (!picker_->Pick(x, y) || std::fabs(picker_->GetFacing()) < min_facing)
    return false;
  picker_->GetPoint(point);
  picker_->GetNormal(normal);
  if (picker_->GetFacing() < 0.0)
    for (int c = 0; c < 3; ++c)
      normal[c] = -normal[c];
  return true;
}

void BrushCursor::place(bool on, const double point[3], const double normal[3], double radius)
{
  if (on) {
    const double lift = 0.02 * radius; // above the surface, so it is not hidden in it
    shape_->SetCenter(point[0] + lift * normal[0], point[1] + lift * normal[1], point[2] + lift * normal[2]);
    shape_->SetNormal(normal[0], normal[1], normal[2]);
    shape_->SetRadius(radius);
  }
  ring_->SetVisibility(on);
}

} // namespace meshpaint
