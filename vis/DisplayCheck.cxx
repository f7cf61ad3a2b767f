#include "DisplayCheck.h"

#include "core/errors.h" // for meshpaint::DeviceError

#include <cstdlib> // for std::getenv
#include <string>  // for std::string

#include <X11/Xlib.h> // for XOpenDisplay, XCloseDisplay (last: its macros)

namespace meshpaint {

void require_display()
{
  const char* name = std::getenv("DISPLAY");
  Display* display = name && *name ? XOpenDisplay(name) : nullptr;
  if (!display)
    throw DeviceError(name && *name ? "cannot open the X display '" + std::string(name) +
                                        "': run under xvfb-run -a, or set DISPLAY to a display that works"
                                    : "no X display to render with: run under xvfb-run -a, or set DISPLAY");
  XCloseDisplay(display);
}

} // namespace meshpaint
