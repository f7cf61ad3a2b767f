// The interactive window's brush: what the keys change, shown on screen,
// turned into strokes.
#ifndef BrushSettings_h
#define BrushSettings_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "core/vec.h"     // for meshpaint::Vec3
#include "paint/stroke.h" // for meshpaint::Stroke

#include <array>  // for std::array
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
  //! The fill of the label channel at `point` with the label tool's class
  //! and guards (a stroke of one point, the radius the distance it may lie
  //! off the surface), checked as stroke() checks.
  Stroke fill_stroke(const Vec3& point) const;
  //! The keys the brush reacts to, one per line.
  static std::string key_help();

  //@{
  //! The settings one by one, for panels (the keys change the same ones).
  //! Names as in stroke scripts; a setter given a name not in its list
  //! throws InputError.
  static const std::vector<std::string>& tools();
  static const std::vector<std::string>& channels(); //!< of the paint tool; "material" paints a coat
  static const std::vector<std::string>& falloffs();
  static const std::vector<std::string>& ops();
  static const std::vector<std::string>& spaces();
  std::string tool() const;
  void set_tool(const std::string& tool);
  std::string channel() const;
  void set_channel(const std::string& channel);
  //! The swatch keys 0..9 set: colour, value k/9, height, label id k.
  int swatch() const { return swatch_; }
  void set_swatch(int k);
  //! The colour painted into diffuse, specular or a material coat (the
  //! swatch's until set).
  std::array<double, 3> colour() const { return colour_; }
  void set_colour(const std::array<double, 3>& rgb) { colour_ = rgb; }
  //! The swatch colours, 0..9.
  static std::array<double, 3> swatch_colour(int k);
  //! The class id the label tool paints (the swatch's until set).
  int label() const { return label_; }
  void set_label(int id);
  //! Label strokes and fills: classes never overwritten, and the one class
  //! overwritten (-1: any), as the stroke keys locked_labels and
  //! only_over_label.
  const std::vector<int>& locked_labels() const { return locked_labels_; }
  void set_locked_labels(const std::vector<int>& ids);
  int only_over_label() const { return only_over_label_; }
  void set_only_over_label(int id);
  //! Fills connect texels across the texel grid's corners too (the stroke
  //! key connect: diagonals), not only along its sides (the default).
  bool fill_diagonals() const { return fill_diagonals_; }
  void set_fill_diagonals(bool on) { fill_diagonals_ = on; }
  double strength() const { return strength_; }
  void set_strength(double strength);
  std::string falloff() const;
  void set_falloff(const std::string& falloff);
  std::string op() const;
  void set_op(const std::string& op);
  std::string space() const;
  void set_space(const std::string& space);
  //! -1 off, 0..2 across x, y, z.
  int mirror() const { return mirror_; }
  void set_mirror(int axis) { mirror_ = axis < 0 || axis > 2 ? -1 : axis; }
  bool backfaces() const { return backfaces_; }
  void set_backfaces(bool on) { backfaces_ = on; }
  void set_spacing(double spacing);
  //! The level geometry tools edit (keys l / L), 1 to the painting level;
  //! a level out of that range is clamped into it.
  int edit_level() const { return edit_level_; }
  void set_edit_level(int level);
  //! The painting level, when the surfaces were rebuilt at another one;
  //! the edit level keeps its value where the new level allows it.
  void set_level(int level);
  //@}

  double radius() const { return radius_; }
  //! True when strokes edit geometry at a level coarser than the painting level.
  bool coarse_edit() const;
  double spacing() const { return spacing_; }
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
  std::array<double, 3> colour_; // colour channels: the swatch's colour, or one set
  int label_ = 1;                // the label tool's class id
  std::vector<int> locked_labels_; // label strokes: classes kept
  int only_over_label_ = -1;       // label strokes: the one class painted over, -1 any
  bool fill_diagonals_ = false;    // fills: 8-connected texels
  double spacing_ = 0.25;
  bool backfaces_ = false;
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
