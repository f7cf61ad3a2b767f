// The studio's entry point: a Qt application showing a painting view.
#pragma once

class vtkPaintView;

namespace meshpaint::studio {

//! Runs the studio on `view` (its surface loaded, not yet initialized)
//! until its window closes; returns the application's exit code.
//! \throw DeviceError when the view cannot be shown.
int run_studio(vtkPaintView* view);

//! Sets the OpenGL surface format VTK's Qt widget needs; call before the
//! QApplication is made.
void prepare_qt();

} // namespace meshpaint::studio
