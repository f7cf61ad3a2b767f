// The painting window's key bindings beside the brush's (BrushSettings):
// what each key does, and the help overlay that lists them.
#ifndef WindowKeys_h
#define WindowKeys_h

#include <string> // for std::string

namespace meshpaint {

//! What a key asks of the window.
enum class WindowKey
{
  none,         //!< not a key of the window
  brush,        //!< perhaps the brush's: BrushSettings::handle_key() decides
  undo,         //!< Ctrl+Z
  redo,         //!< Ctrl+Y
  save,         //!< Ctrl+S
  export_model, //!< Ctrl+E
  help,         //!< h, F1, ?
  subsurface,   //!< b: subsurface light at rest, on or off
  shown_next,   //!< v: show the next channel (diffuse, label, ...)
  shown_back,   //!< V: the previous one
  reset_camera, //!< r
  eyedropper,   //!< e: the class or colour under the mouse into the brush
  fill,         //!< g: the region under the mouse filled with the brush's class
  fill_connect, //!< G: fills connect along sides only / across corners too
  quit          //!< q, Escape
};

//! The binding of VTK key symbol `keysym` ("z", "bracketleft", "F1", ...)
//! with Ctrl held (`control`) or not.
WindowKey window_key(const std::string& keysym, bool control);

//! The help overlay: the brush's keys, then the mouse and the window's keys.
std::string window_help();

} // namespace meshpaint

#endif
