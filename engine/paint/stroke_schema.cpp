#include "paint/stroke_schema.h"

#include <stdexcept> // for std::logic_error

namespace meshpaint {
namespace {

constexpr ToolSet bits(std::initializer_list<Tool> tools)
{
  ToolSet out = 0;
  for (Tool t : tools)
    out |= tool_bit(t);
  return out;
}

//! Tools with a path and a brush: all but wash, dip and merge.
constexpr ToolSet kBrushTools = kAllTools & ~bits({Tool::Wash, Tool::Dip, Tool::Merge});
//! Tools of the paint equation.
constexpr ToolSet kPaintTools = bits({Tool::Paint, Tool::Label, Tool::Wash, Tool::Dip});
//! Label edits: a class into a connected region, one class into another.
constexpr ToolSet kLabelEdits = bits({Tool::Fill, Tool::Merge});
//! What a fill leaves out of a brush: it fills the region at one point.
constexpr ToolSet kNotFill = ~tool_bit(Tool::Fill);
constexpr ToolSet kSmoothTools = bits({Tool::Smooth, Tool::Blur});
//! Tools that move the surface (smooth only of positions).
constexpr ToolSet kShapeTools = bits({Tool::Sculpt, Tool::Inflate, Tool::Flatten, Tool::Grab, Tool::Smooth});
//! Tools that change colours on one side of a two-sided surface (smooth only of
//! colours).
constexpr ToolSet kSidedTools = bits({Tool::Paint, Tool::Wash, Tool::Dip, Tool::Blur, Tool::Smear, Tool::Smooth});

// Built on first use, so that other files' static data may read them.
const std::vector<StrokeKey>& stroke_table()
{
  // Tool names in the order of enum Tool.
  static const std::vector<KeyName> kToolNames = {
    {"paint", int(Tool::Paint)},   {"label", int(Tool::Label)},     {"wash", int(Tool::Wash)},
    {"dip", int(Tool::Dip)},       {"smooth", int(Tool::Smooth)},   {"blur", int(Tool::Blur)},
    {"sculpt", int(Tool::Sculpt)}, {"inflate", int(Tool::Inflate)}, {"flatten", int(Tool::Flatten)},
    {"smear", int(Tool::Smear)},   {"grab", int(Tool::Grab)},       {"fill", int(Tool::Fill)},
    {"merge", int(Tool::Merge)}};

  // Adding a key: a row here (in the order messages list the keys), its
  // reading in read_stroke() (stroke.cpp), its writing in stroke_object()
  // (stroke_json.cpp) and a row in docs/strokes.md (tests check the rows
  // match).
  static const std::vector<StrokeKey> kStrokeKeys = {
    {"tool", KeyType::Word, 0, 0, kToolNames, kAllTools, "paint", "Stroke::tool"},
    {"points", KeyType::Points, 0, 0, {}, kBrushTools, "", "Stroke::points"},
    {"radius", KeyType::Number, 1e-30, 1e30, {}, kBrushTools, "", "Brush::radius"},
    {"strength", KeyType::Number, 0.0, 1.0, {}, kAllTools, "1", "Brush::strength"},
    {"falloff",
     KeyType::Word,
     0,
     0,
     {{"constant", FALLOFF_CONSTANT},
      {"linear", FALLOFF_LINEAR},
      {"smoothstep", FALLOFF_SMOOTHSTEP},
      {"gaussian", FALLOFF_GAUSSIAN}},
     kBrushTools,
     "smoothstep",
     "Brush::falloff"},
    {"spacing", KeyType::Number, 0.01, 100.0, {}, kBrushTools, "0.25", "Brush::spacing"},
    // "blur" and "smear" are brushes of their own, named as ops of a paint
    // stroke.
    {"op",
     KeyType::Word,
     0,
     0,
     {{"copy", PAINT_OP_COPY},
      {"over", PAINT_OP_OVER},
      {"max", PAINT_OP_MAX},
      {"add", PAINT_OP_ADD},
      {"subtract", PAINT_OP_SUBTRACT},
      {"blur", -1},
      {"smear", -1}},
     kPaintTools | kLabelEdits | bits({Tool::Blur, Tool::Smear}),
     "copy",
     "PaintSettings::op"},
    {"channels", KeyType::Object, 0, 0, {}, kPaintTools | kLabelEdits, "", "PaintSettings::value, alpha"},
    {"alphas", KeyType::Object, 0, 0, {}, kPaintTools | kLabelEdits, "1", "PaintSettings::alpha"},
    {"pressure", KeyType::Numbers, 0.0, 1.0, {}, kBrushTools & kNotFill, "1", "Stroke::pressure"},
    {"mirror",
     KeyType::Word,
     0,
     0,
     {{"x", 0}, {"y", 1}, {"z", 2}},
     kBrushTools & kNotFill & ~tool_bit(Tool::Grab),
     "",
     "Brush::mirror_axis"},
    {"amount",
     KeyType::Number,
     -1e30,
     1e30,
     {},
     bits({Tool::Sculpt, Tool::Inflate, Tool::Flatten}),
     "",
     "MoveSettings::amount"},
    {"iterations", KeyType::Integer, 1, 1000, {}, kSmoothTools, "1", "SmoothSettings::iterations"},
    {"target",
     KeyType::Word,
     0,
     0,
     {{"position", 0}, {"color", 1}},
     tool_bit(Tool::Smooth),
     "position",
     "SmoothSettings::target_colour"},
    {"method", KeyType::Word, 0, 0, {{"laplacian", 0}, {"taubin", 1}}, kSmoothTools, "", "SmoothSettings::taubin"},
    {"lambda", KeyType::Number, 0.0, 1.0, {}, kSmoothTools, "0.5", "SmoothSettings::lambda"},
    {"mu", KeyType::Number, -1.0, 0.0, {}, kSmoothTools, "-0.53", "SmoothSettings::mu"},
    {"mode",
     KeyType::Word,
     0,
     0,
     {{"material", 0}, {"remover", 1}, {"dye", 2}, {"polish", 3}, {"sandpaper", 4}},
     bits({Tool::Paint, Tool::Wash, Tool::Dip}),
     "",
     "PaintSettings::remover, specular_coefficient, value, alpha"},
    {"coefficient",
     KeyType::Number,
     0.0,
     1.0,
     {},
     bits({Tool::Paint, Tool::Wash, Tool::Dip}),
     "",
     "PaintSettings::specular_coefficient"},
    {"pattern", KeyType::Object, 0, 0, {}, kPaintTools, "", "PaintSettings::pattern"},
    {"stroke",
     KeyType::Word,
     0,
     0,
     {{"interpolated", 0}, {"rubberband", 1}, {"rubberstamp", 2}},
     kBrushTools & kNotFill,
     "interpolated",
     "Stroke::points, pressure"},
    {"stamp", KeyType::File, 0, 0, {}, kBrushTools & ~bits({Tool::Label, Tool::Fill}), "", "Brush::stamp_file"},
    {"edit_level",
     KeyType::Integer,
     1,
     12,
     {},
     kShapeTools,
     "",
     "SmoothSettings::edit_level, MoveSettings::edit_level"},
    {"space",
     KeyType::Word,
     0,
     0,
     {{"object", SPACE_OBJECT},
      {"tangent", SPACE_TANGENT},
      {"screen", SPACE_SCREEN},
      {"parameter", SPACE_PARAMETER}},
     kBrushTools & kNotFill,
     "object",
     "Brush::space"},
    {"camera", KeyType::Object, 0, 0, {}, kAllTools, "", "Brush::camera, has_camera"},
    {"backfaces", KeyType::Word, 0, 0, {{"skip", 0}, {"paint", 1}}, kBrushTools, "skip", "Brush::paint_backfaces"},
    {"spray",
     KeyType::Object,
     0,
     0,
     {},
     bits({Tool::Paint, Tool::Label}),
     "",
     "PaintSettings::spray_drops, spray_size, spray_seed"},
    {"side",
     KeyType::Word,
     0,
     0,
     {{"auto", 0}, {"outside", 1}, {"inside", 2}},
     kSidedTools,
     "auto",
     "Brush::side"},
    // Which classes a stroke that paints the label channel may overwrite
    // (read_label_guards() in stroke.cpp also requires that channel).
    {"locked_labels",
     KeyType::Ids,
     0,
     16777216,
     {},
     kPaintTools | kLabelEdits,
     "",
     "PaintSettings::locked_labels"},
    {"only_over_label",
     KeyType::Integer,
     0,
     16777216,
     {},
     kPaintTools | kLabelEdits,
     "",
     "PaintSettings::only_over_label"},
    // How a fill's region grows from texel to texel.
    {"connect",
     KeyType::Word,
     0,
     0,
     {{"sides", 0}, {"diagonals", 1}},
     tool_bit(Tool::Fill),
     "sides",
     "PaintSettings::fill_diagonals"}};
  return kStrokeKeys;
}

const std::vector<StrokeKey>& pattern_table()
{

  static const std::vector<StrokeKey> kPatternKeys = {
    {"type",
     KeyType::Word,
     0,
     0,
     {{"noise", PATTERN_NOISE},
      {"turbulence", PATTERN_TURBULENCE},
      {"marble", PATTERN_MARBLE},
      {"bath", PATTERN_BATH},
      {"image", PATTERN_IMAGE},
      {"volume", PATTERN_VOLUME}},
     kPaintTools,
     "",
     "Pattern::kind"},
    {"coord",
     KeyType::Word,
     0,
     0,
     {{"position", PATTERN_COORD_POSITION}, {"uv", PATTERN_COORD_UV}, {"screen", PATTERN_COORD_SCREEN}},
     kPaintTools,
     "position",
     "Pattern::coord"},
    {"matte",
     KeyType::Word,
     0,
     0,
     {{"self", MATTE_SELF}, {"opaque", MATTE_OPAQUE}},
     kPaintTools,
     "self",
     "Pattern::matte"},
    {"scale", KeyType::Number, 0.0, 1e308, {}, kPaintTools, "1", "Pattern::transform (multiplied)"},
    {"octaves", KeyType::Integer, 1, 12, {}, kPaintTools, "4", "Pattern::octaves"},
    {"transform", KeyType::Numbers, 0, 0, {}, kPaintTools, "identity", "Pattern::transform"},
    {"file", KeyType::File, 0, 0, {}, kPaintTools, "", "Pattern::file"}};
  return kPatternKeys;
}

const StrokeKey& find_key(const std::vector<StrokeKey>& keys, const std::string& name)
{
  for (const StrokeKey& k : keys)
    if (name == k.name)
      return k;
  throw std::logic_error("no stroke key \"" + name + "\" in the schema");
}

} // namespace

std::string join_names(const std::vector<std::string>& words)
{
  std::string out;
  for (const std::string& w : words)
    out += (out.empty() ? "" : ", ") + w;
  return out;
}

const std::vector<StrokeKey>& stroke_keys() { return stroke_table(); }
const std::vector<StrokeKey>& pattern_keys() { return pattern_table(); }
const StrokeKey& stroke_key(const std::string& name) { return find_key(stroke_table(), name); }
const StrokeKey& pattern_key(const std::string& name) { return find_key(pattern_table(), name); }

std::vector<std::string> key_names(const StrokeKey& key)
{
  std::vector<std::string> out;
  for (const KeyName& n : key.names)
    out.emplace_back(n.name);
  return out;
}

std::string name_list(const StrokeKey& key) { return join_names(key_names(key)); }

std::string key_list(const std::vector<StrokeKey>& keys)
{
  std::vector<std::string> names;
  for (const StrokeKey& k : keys)
    names.emplace_back(k.name);
  return join_names(names);
}

const char* name_of(const StrokeKey& key, int value)
{
  for (const KeyName& n : key.names)
    if (n.value == value)
      return n.name;
  throw std::logic_error("stroke key \"" + std::string(key.name) + "\" has no name for " + std::to_string(value));
}

int value_of(const StrokeKey& key, const std::string& name)
{
  for (const KeyName& n : key.names)
    if (name == n.name)
      return n.value;
  throw std::logic_error("stroke key \"" + std::string(key.name) + "\" has no name \"" + name + "\"");
}

const std::vector<std::string>& channel_names()
{
  static const std::vector<std::string> names = {"diffuse",      "specular", "roughness",
                                                 "displacement", "label",    "mask"};
  return names;
}

} // namespace meshpaint
