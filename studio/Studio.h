// The studio's entry point: a Qt application showing a painting view.
#pragma once

#include <string> // for std::string

class vtkPaintView;

namespace meshpaint::studio {

//! The OpenCL device selector and atlas storage the studio's preferences
//! keep (PreferencesDialog), empty for the defaults; `meshpaint view` uses
//! them where --device and --storage are not given.
struct DeviceChoice
{
  std::string device, storage;
};
DeviceChoice preferred_device();

//! Runs the studio on `view` (its surface loaded, not yet initialized)
//! until its window closes; returns the application's exit code.
//! \throw DeviceError when the view cannot be shown.
int run_studio(vtkPaintView* view);

//! Sets the OpenGL surface format VTK's Qt widget needs and the names the
//! settings are kept under (unless set); call before the QApplication is made.
void prepare_qt();

} // namespace meshpaint::studio
