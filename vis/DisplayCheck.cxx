#include "DisplayCheck.h"

#include "core/errors.h" // for meshpaint::DeviceError

#include <cstdlib> // for std::getenv
#include <string>  // for std::string

#include <X11/Xlib.h> // for XOpenDisplay (last: its macros)

namespace meshpaint {

void require_display()
{
  // The connection stays open: closing the only client's connection makes
  // an X server such as Xvfb reset, and a window opened just then fails.
  static Display* display = nullptr;
  if (display)
    return;
  const char* name = std::getenv("DISPLAY");
  display = name && *name ? XOpenDisplay(name) : nullptr;
  if (!display)
    throw DeviceError(name && *name ? "cannot open the X display '" + std::string(name) +
                                        "': run under xvfb-run -a, or set DISPLAY to a display that works"
                                    : "no X display to render with: run under xvfb-run -a, or set DISPLAY");
}

} // namespace meshpaint
