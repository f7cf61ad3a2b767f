#include "BrushSettings.h"

#include "core/errors.h"     // for meshpaint::InputError
#include "core/format.h"     // for meshpaint::format_fixed
#include "paint/stroke_schema.h" // for meshpaint::stroke_key
#include "project/labels.h"  // for meshpaint::kMaxLabelId

#include <algorithm> // for std::clamp
#include <array>     // for std::array
#include <cmath>     // for std::round
#include <sstream>   // for std::ostringstream

namespace meshpaint {
namespace {

const std::vector<std::string> kTools = {"paint", "smooth", "blur", "sculpt", "inflate", "flatten", "grab",
                                         "smear", "label"};
const std::vector<std::string> kChannels = {"diffuse", "specular", "roughness", "displacement", "mask", "material"};
//! The names of a stroke key whose values are a member's (for a word key
//! such as "falloff", in the order of their values).
std::vector<std::string> member_names(const char* key)
{
  std::vector<std::string> out;
  for (const KeyName& n : stroke_key(key).names)
    if (n.value >= 0) // op "blur" and "smear" are tools of their own
      out.emplace_back(n.name);
  return out;
}

const std::vector<std::string>& falloff_names()
{
  static const std::vector<std::string> names = member_names("falloff");
  return names;
}

const std::vector<std::string>& op_names()
{
  static const std::vector<std::string> names = member_names("op");
  return names;
}

const std::vector<std::string>& space_names()
{
  static const std::vector<std::string> names = member_names("space");
  return names;
}
// Swatches 0..9 for the colour channels.
const std::array<std::array<double, 3>, 10> kPalette = {{{0.05, 0.05, 0.05}, {0.85, 0.1, 0.1}, {0.95, 0.55, 0.1},
                                                         {0.95, 0.9, 0.2}, {0.2, 0.7, 0.2}, {0.1, 0.6, 0.7},
                                                         {0.15, 0.25, 0.85}, {0.55, 0.2, 0.75}, {0.6, 0.4, 0.25},
                                                         {0.95, 0.95, 0.95}}};

template <typename A>
int cycle(int v, const A& list, bool back)
{
  const int n = int(list.size());
  return (v + (back ? n - 1 : 1)) % n;
}

bool is_paint(const std::string& tool) { return tool == "paint"; }

//! Tools that move the surface and so may work at a coarser level.
bool moves(const std::string& tool)
{
  return tool == "smooth" || tool == "sculpt" || tool == "inflate" || tool == "flatten" || tool == "grab";
}

} // namespace

BrushSettings::BrushSettings(double size, int level)
  : size_(size > 0 ? size : 1.0), colour_(kPalette[1]), radius_(0.03 * size_), level_(level), edit_level_(level)
{
}

const std::vector<std::string>& BrushSettings::tools() { return kTools; }
const std::vector<std::string>& BrushSettings::channels() { return kChannels; }
const std::vector<std::string>& BrushSettings::falloffs() { return falloff_names(); }
const std::vector<std::string>& BrushSettings::ops() { return op_names(); }
const std::vector<std::string>& BrushSettings::spaces() { return space_names(); }
std::string BrushSettings::tool() const { return kTools[std::size_t(tool_)]; }
void BrushSettings::set_tool(const std::string& tool) { tool_ = index_of_name(kTools, tool, "the tool"); }
std::string BrushSettings::channel() const { return kChannels[std::size_t(channel_)]; }
void BrushSettings::set_channel(const std::string& channel) { channel_ = index_of_name(kChannels, channel, "the channel"); }
std::string BrushSettings::falloff() const { return falloff_names()[std::size_t(falloff_)]; }
void BrushSettings::set_falloff(const std::string& falloff) { falloff_ = index_of_name(falloff_names(), falloff, "the falloff"); }
std::string BrushSettings::op() const { return op_names()[std::size_t(op_)]; }
void BrushSettings::set_op(const std::string& op) { op_ = index_of_name(op_names(), op, "the op"); }
std::string BrushSettings::space() const { return space_names()[std::size_t(space_)]; }
void BrushSettings::set_space(const std::string& space) { space_ = index_of_name(space_names(), space, "the brush space"); }
std::array<double, 3> BrushSettings::swatch_colour(int k) { return kPalette[std::size_t(std::clamp(k, 0, 9))]; }

void BrushSettings::set_swatch(int k)
{
  swatch_ = std::clamp(k, 0, 9);
  colour_ = kPalette[std::size_t(swatch_)];
  label_ = swatch_;
}

void BrushSettings::set_label(int id)
{
  if (id < 0 || id > kMaxLabelId)
    throw InputError("a label id must be 0 to " + std::to_string(kMaxLabelId) + ", not " + std::to_string(id));
  label_ = id;
}

void BrushSettings::set_locked_labels(const std::vector<int>& ids)
{
  for (const int id : ids)
    if (id < 0 || id > kMaxLabelId)
      throw InputError("a label id must be 0 to " + std::to_string(kMaxLabelId) + ", not " + std::to_string(id));
  locked_labels_ = ids;
}

void BrushSettings::set_only_over_label(int id)
{
  if (id < -1 || id > kMaxLabelId)
    throw InputError("a label id must be 0 to " + std::to_string(kMaxLabelId) + ", not " + std::to_string(id));
  only_over_label_ = id;
}

Stroke BrushSettings::fill_stroke(const Vec3& point) const
{
  Stroke s = make_stroke(Tool::Fill);
  s.points = {point};
  s.brush.radius = float(radius_);
  s.paint().value[CHANNEL_LABEL] = {float(label_), float(label_), float(label_), 1.f};
  s.paint().alpha[CHANNEL_LABEL] = 1.f;
  s.paint().locked_labels = locked_labels_;
  s.paint().only_over_label = only_over_label_;
  s.paint().fill_diagonals = fill_diagonals_;
  check_stroke(s);
  return s;
}

void BrushSettings::set_strength(double strength)
{
  strength_ = std::clamp(strength, 0.0, 1.0);
}

void BrushSettings::set_spacing(double spacing)
{
  spacing_ = std::clamp(spacing, 0.01, 100.0);
}

void BrushSettings::set_edit_level(int level) { edit_level_ = std::clamp(level, 1, level_); }

void BrushSettings::set_level(int level)
{
  const bool finest = edit_level_ == level_;
  level_ = std::max(1, level);
  edit_level_ = finest ? level_ : std::min(edit_level_, level_);
}

bool BrushSettings::coarse_edit() const
{
  return moves(kTools[std::size_t(tool_)]) && edit_level_ < level_;
}

bool BrushSettings::handle_key(const std::string& key, bool shift)
{
  if (key == "t" || key == "T")
    tool_ = cycle(tool_, kTools, shift || key == "T");
  else if (key == "c" || key == "C")
    channel_ = cycle(channel_, kChannels, shift || key == "C");
  else if (key.size() == 1 && key[0] >= '0' && key[0] <= '9')
    set_swatch(key[0] - '0');
  else if (key == "bracketright")
    radius_ *= 1.25;
  else if (key == "bracketleft")
    radius_ /= 1.25;
  else if (key == "plus" || key == "equal" || key == "KP_Add")
    strength_ = std::clamp(strength_ + 0.1, 0.1, 1.0);
  else if (key == "minus" || key == "KP_Subtract")
    strength_ = std::clamp(strength_ - 0.1, 0.1, 1.0);
  else if (key == "f" || key == "F")
    falloff_ = cycle(falloff_, falloff_names(), shift || key == "F");
  else if (key == "o" || key == "O")
    op_ = cycle(op_, op_names(), shift || key == "O");
  else if (key == "m" || key == "M")
    mirror_ = mirror_ == 2 ? -1 : mirror_ + 1;
  else if (key == "i" || key == "I")
    inwards_ = !inwards_;
  else if (key == "p" || key == "P")
    space_ = cycle(space_, space_names(), shift || key == "P");
  else if (key == "l" && !shift)
    edit_level_ = std::max(1, edit_level_ - 1);
  else if (key == "L" || (key == "l" && shift))
    edit_level_ = std::min(level_, edit_level_ + 1);
  else
    return false;
  // Keep the strength on the grid of its steps, so what is shown is what is painted.
  strength_ = std::round(strength_ * 10.0) / 10.0;
  return true;
}

Stroke BrushSettings::stroke(const std::vector<Vec3>& points) const
{
  const std::string tool = kTools[std::size_t(tool_)];
  Stroke s = make_stroke(tool_named(tool));
  s.points = points;
  s.brush.radius = float(radius_);
  s.brush.strength = float(strength_);
  s.brush.falloff = falloff_;
  s.brush.spacing = float(spacing_);
  s.brush.paint_backfaces = backfaces_;
  if (tool != "grab") // a grab pulls one region
    s.brush.mirror_axis = mirror_;
  const auto paint = [&s](int channel, double r, double g, double b) {
    s.paint().value[std::size_t(channel)] = {float(r), float(g), float(b), 1.f};
    s.paint().alpha[std::size_t(channel)] = 1.f;
  };
  if (is_paint(tool)) {
    const auto& rgb = colour_;
    const std::string channel = kChannels[std::size_t(channel_)];
    const double level = swatch_ / 9.0, height = (swatch_ - 5) * 0.004 * size_; // 5: the unpainted height
    if (channel == "diffuse")
      paint(CHANNEL_DIFFUSE, rgb[0], rgb[1], rgb[2]);
    else if (channel == "specular")
      paint(CHANNEL_SPECULAR, rgb[0], rgb[1], rgb[2]);
    else if (channel == "roughness")
      paint(CHANNEL_ROUGHNESS, level, level, level);
    else if (channel == "displacement")
      paint(CHANNEL_DISPLACEMENT, height, height, height);
    else if (channel == "mask")
      paint(CHANNEL_MASK, level, level, level);
    else { // a coat: colour, a matching specular, and the swatch's roughness
      paint(CHANNEL_DIFFUSE, rgb[0], rgb[1], rgb[2]);
      paint(CHANNEL_SPECULAR, 0.5, 0.5, 0.5);
      paint(CHANNEL_ROUGHNESS, 0.3, 0.3, 0.3);
    }
    s.paint().op = op_;
  } else if (tool == "label") {
    paint(CHANNEL_LABEL, label_, label_, label_);
    s.paint().locked_labels = locked_labels_;
    s.paint().only_over_label = only_over_label_;
  } else if (tool == "sculpt" || tool == "inflate") {
    s.move().amount = float((inwards_ ? -0.1 : 0.1) * radius_);
  } else if (tool == "flatten") {
    s.move().amount = 0.5f;
  }
  if (coarse_edit())
    s.set_edit_level(edit_level_);
  s.brush.space = space_;
  if (space_ == SPACE_SCREEN && has_camera_) { // the view it is drawn in
    s.brush.camera = camera_;
    s.brush.has_camera = true;
  }
  check_stroke(s);
  return s;
}

std::string BrushSettings::describe() const
{
  const std::string tool = kTools[std::size_t(tool_)];
  std::ostringstream out;
  out << "tool " << tool;
  if (is_paint(tool))
    out << "   channel " << kChannels[std::size_t(channel_)] << "   swatch " << swatch_ << "   op "
        << op_names()[std::size_t(op_)];
  else if (tool == "label") {
    out << "   label " << label_;
    for (std::size_t k = 0; k < locked_labels_.size(); ++k)
      out << (k == 0 ? "   locked " : ",") << locked_labels_[k];
    if (only_over_label_ >= 0)
      out << "   only over " << only_over_label_;
    out << "   fill " << (fill_diagonals_ ? "diagonals" : "sides");
  }
  else if (tool == "sculpt" || tool == "inflate")
    out << (inwards_ ? "   inwards" : "   outwards");
  if (moves(tool))
    out << "   edit level " << edit_level_ << (edit_level_ < level_ ? " (coarse)" : "");
  out << "\nradius " << format_fixed(radius_, 4) << "   strength " << format_fixed(strength_, 1) << "   falloff "
      << falloff_names()[std::size_t(falloff_)] << "   mirror " << (mirror_ < 0 ? std::string("off") : std::string(1, char('x' + mirror_)))
      << "   space " << space_names()[std::size_t(space_)];
  return out.str();
}

std::string BrushSettings::key_help()
{
  return "t / T        next / previous tool (paint smooth blur sculpt inflate flatten grab smear label)\n"
         "c / C        next / previous channel (diffuse specular roughness displacement mask material)\n"
         "0 .. 9       swatch: colour, value, height or label id\n"
         "[ / ]        smaller / larger brush\n"
         "- / +        less / more strength\n"
         "f            falloff (constant linear smoothstep gaussian)\n"
         "o            op (copy over max add subtract)\n"
         "m            mirror (off x y z)\n"
         "i            sculpt and inflate: outwards / inwards\n"
         "p / P        brush space (object tangent screen parameter)\n"
         "l / L        geometry tools: edit a coarser / finer level";
}

} // namespace meshpaint
