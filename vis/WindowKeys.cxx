#include "WindowKeys.h"

#include "BrushSettings.h" // for meshpaint::BrushSettings::key_help

namespace meshpaint {

WindowKey window_key(const std::string& key, bool control)
{
  if (control) {
    if (key == "z" || key == "Z")
      return WindowKey::undo;
    if (key == "y" || key == "Y")
      return WindowKey::redo;
    if (key == "s" || key == "S")
      return WindowKey::save;
    if (key == "e" || key == "E")
      return WindowKey::export_model;
    return WindowKey::none;
  }
  if (key == "h" || key == "F1" || key == "question")
    return WindowKey::help;
  if (key == "b")
    return WindowKey::subsurface;
  if (key == "v")
    return WindowKey::shown_next;
  if (key == "V")
    return WindowKey::shown_back;
  if (key == "r")
    return WindowKey::reset_camera;
  if (key == "e")
    return WindowKey::eyedropper;
  if (key == "g")
    return WindowKey::fill;
  if (key == "G")
    return WindowKey::fill_connect;
  if (key == "q" || key == "Escape")
    return WindowKey::quit;
  return WindowKey::brush;
}

std::string window_help()
{
  return BrushSettings::key_help() +
         "\nleft-drag    paint (off the surface, or with Alt: turn the camera)\n"
         "middle-drag  pan;  right-drag, wheel: zoom\n"
         "Ctrl+Z / Ctrl+Y  undo / redo\n"
         "Ctrl+S       save strokes.json and surface.vtp\n"
         "Ctrl+E       export model.obj with texture maps\n"
         "r            reset the camera\n"
         "e            eyedropper: the class (label tool) or colour under the mouse into the brush\n"
         "g / G        fill the region under the mouse with the label class / fills connect diagonally (on / off)\n"
         "b            subsurface light at rest (on / off)\n"
         "v / V        show the next / previous channel (diffuse label specular roughness displacement mask)\n"
         "h, F1        this help;  q, Escape: quit";
}

} // namespace meshpaint
