/**
 * @class vtkPaintInteractorStyle
 * @brief Mouse and keys of the painting window.
 *
 * Left-drag on the surface paints; left-drag off the surface, or with Alt,
 * turns the camera as vtkInteractorStyleTrackballCamera does, whose other
 * controls (middle: pan, right and wheel: zoom, Shift + left: pan, Ctrl +
 * left: spin) stay as they are. Events become calls on a
 * meshpaint::PaintControls (vtkPaintView gives the style its own): strokes,
 * the cursor, keys, and the start and end of camera interaction. VTK's own
 * key bindings (wireframe, stereo, ...) are off.
 */
#ifndef vtkPaintInteractorStyle_h
#define vtkPaintInteractorStyle_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <vtkInteractorStyleTrackballCamera.h> // for vtkInteractorStyleTrackballCamera

namespace meshpaint {
class PaintControls;
}

class MESHPAINTVIS_EXPORT vtkPaintInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static vtkPaintInteractorStyle* New();
  vtkTypeMacro(vtkPaintInteractorStyle, vtkInteractorStyleTrackballCamera);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /// What events turn into (not owned: it outlives the style); null: the
  /// trackball camera alone.
  void SetControls(meshpaint::PaintControls* controls) { this->Controls = controls; }
#endif

  void OnLeftButtonDown() override;
  void OnLeftButtonUp() override;
  void OnMouseMove() override;
  void OnKeyPress() override;
  void OnChar() override;

protected:
  vtkPaintInteractorStyle();
  ~vtkPaintInteractorStyle() override = default;

  meshpaint::PaintControls* Controls = nullptr;

private:
  vtkPaintInteractorStyle(const vtkPaintInteractorStyle&) = delete;
  void operator=(const vtkPaintInteractorStyle&) = delete;

  //! Start and end of a camera interaction.
  void OnInteraction(vtkObject*, unsigned long event, void*);
};

#endif
