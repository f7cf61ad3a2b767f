// Whether there is an X display to render with: VTK's windows, offscreen
// ones too, abort the program without one.
#ifndef DisplayCheck_h
#define DisplayCheck_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

namespace meshpaint {

//! Checks that the X display DISPLAY names can be opened.
//! \throw DeviceError in one line saying to run under xvfb-run or set DISPLAY.
MESHPAINTVIS_EXPORT void require_display();

} // namespace meshpaint

#endif
