// The interactive window's brush: what the keys change, shown on screen,
// turned into strokes.
#ifndef BrushSettings_h
#define BrushSettings_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "core/vec.h"     // for meshpaint::Vec3
#include "paint/stroke.h" // for meshpaint::Stroke

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

class MESHPAINTVIS_EXPORT BrushSettings
{
public:
  //! `size`: the surface's bounding-box diagonal; radius and heights scale
  //! with it. `level`: the painting level, the finest edit level.
  BrushSettings(double size, int level);

  //! Applies key `key` (a VTK key symbol such as "t", "bracketleft", "F1");
  //! true when the key is one of the brush's (see key_help()).
  bool handle_key(const std::string& key, bool shift);

  //! The stroke along `points` with these settings, checked as a script's
  //! stroke is (check_stroke()).
  //! \throw InputError if the settings make no valid stroke (they always should).
  Stroke stroke(const std::vector<Vec3>& points) const;

  //! One line per setting, for the window's status text.
  std::string describe() const;
  //! The keys the brush reacts to, one per line.
  static std::string key_help();

  double radius() const { return radius_; }
  //! True when strokes edit geometry at a level coarser than the painting level.
  bool coarse_edit() const;
  double spacing() const { return 0.25; }
  void set_radius(double radius) { radius_ = radius; }
  //! The view screen-space strokes are drawn in.
  void set_camera(const Camera& camera)
  {
    camera_ = camera;
    has_camera_ = true;
  }

private:
  double size_;
  int tool_ = 0;       // index into the tool list
  int channel_ = 0;    // index into the channel list
  int swatch_ = 1;     // 0..9, the value painted into the channel
  double radius_;
  double strength_ = 1.0;
  int falloff_ = 2;    // smoothstep
  int op_ = 0;         // copy
  int mirror_ = -1;    // -1 none, 0..2 x, y, z
  bool inwards_ = false; // sculpt, inflate: push in instead of out
  int level_;            // painting level
  int edit_level_;       // level geometry tools edit, 1..level_
  int space_ = 0;        // object, tangent, screen, parameter
  Camera camera_;
  bool has_camera_ = false;
};

} // namespace meshpaint

#endif
