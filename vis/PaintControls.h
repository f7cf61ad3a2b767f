// What the painting window's mouse and keys can ask of it: the narrow
// interface vtkPaintInteractorStyle calls, so that the style needs nothing
// else of vtkPaintView and the view nothing of the style.
#ifndef PaintControls_h
#define PaintControls_h

#include <string> // for std::string

namespace meshpaint {

class PaintControls
{
public:
  virtual ~PaintControls() = default;

  //! A stroke at display pixels (origin bottom left); false when no surface
  //! faces the viewer there (the camera turns instead).
  virtual bool begin_stroke(int x, int y) = 0;
  virtual void continue_stroke(int x, int y) = 0;
  virtual void end_stroke() = 0;
  //! Whether a stroke is being drawn.
  virtual bool painting() const = 0;
  //! The mouse moved without a button: the brush cursor follows it.
  virtual void hover(int x, int y) = 0;
  //! A key (VTK key symbol) with the modifiers held.
  virtual void key(const std::string& keysym, bool control, bool shift) = 0;
  //! A camera interaction starts (true) or ends (false).
  virtual void camera_moving(bool moving) = 0;
};

} // namespace meshpaint

#endif
