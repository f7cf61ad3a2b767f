/**
 * @class vtkPaintInteractorStyle
 * @brief Mouse and keys of the painting window.
 *
 * Left-drag on the surface paints with vtkPaintView's brush; left-drag off
 * the surface, or with Alt, turns the camera as vtkInteractorStyleTrackballCamera
 * does, whose other controls (middle: pan, right and wheel: zoom, Shift +
 * left: pan, Ctrl + left: spin) stay as they are. Keys go to
 * vtkPaintView::HandleKey(); VTK's own key bindings (wireframe, stereo, ...)
 * are off.
 */
#ifndef vtkPaintInteractorStyle_h
#define vtkPaintInteractorStyle_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkInteractorStyleTrackballCamera.h> // for vtkInteractorStyleTrackballCamera

class vtkPaintView;

class MESHPAINTVIS_EXPORT vtkPaintInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static vtkPaintInteractorStyle* New();
  vtkTypeMacro(vtkPaintInteractorStyle, vtkInteractorStyleTrackballCamera);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The view to paint in (not reference-counted: the view owns the style).
  void SetView(vtkPaintView* view) { this->View = view; }
  vtkPaintView* GetView() { return this->View; }

  void OnLeftButtonDown() override;
  void OnLeftButtonUp() override;
  void OnMouseMove() override;
  void OnKeyPress() override;
  void OnChar() override;

protected:
  vtkPaintInteractorStyle() = default;
  ~vtkPaintInteractorStyle() override = default;

  vtkPaintView* View = nullptr;

private:
  vtkPaintInteractorStyle(const vtkPaintInteractorStyle&) = delete;
  void operator=(const vtkPaintInteractorStyle&) = delete;
};

#endif
