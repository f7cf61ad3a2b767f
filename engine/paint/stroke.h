// Strokes: what the user asked the brush to do, as the stroke script says it.
#pragma once

#include "atlas_types.h" // for CHANNEL_COUNT, FALLOFF_*, PAINT_OP_*
#include "core/errors.h"
#include "core/vec.h"
#include "paint/raster.h"

#include <array>  // for std::array
#include <memory> // for std::shared_ptr
#include <string> // for std::string
#include <variant> // for std::variant
#include <vector> // for std::vector

namespace meshpaint {

enum class Tool
{
  Paint,   //!< the paint equation on the chosen channels
  Label,   //!< paint one class id into the label channel
  Wash,    //!< the paint equation everywhere at once, no brush
  Dip,     //!< a wash through a 3D matte (the stroke's pattern)
  Smooth,  //!< Laplacian or Taubin smoothing of positions (or colours)
  Blur,    //!< smoothing of the colour channels
  Sculpt,  //!< move along the normal at the brush centre
  Inflate, //!< move along each point's own normal
  Flatten, //!< move towards the plane through the centre
  Smear,   //!< drag the colours along the stroke: each dab lays down what the previous one picked up
  Grab,    //!< pull the surface around the first point along the path
  Fill,    //!< a class id into the connected region of one class around a point
  Merge    //!< every texel of one class becomes another class
};

//! Name of a tool as the stroke script writes it.
const char* tool_name(Tool tool);
//! Wash, dip and merge: everywhere at once, with no path or brush.
inline bool covers_everything(Tool tool) { return tool == Tool::Wash || tool == Tool::Dip || tool == Tool::Merge; }
//! The tool of that name. \throw InputError for a name that is none.
Tool tool_named(const std::string& name);

//! A view, as VTK's camera gives it: what screen-space brushes and patterns
//! project with.
struct Camera
{
  Vec3 position{0.f, 0.f, 1.f};
  Vec3 focal_point{0.f, 0.f, 0.f};
  Vec3 view_up{0.f, 1.f, 0.f};
  float view_angle = 30.f; //!< degrees, vertical
  bool operator==(const Camera& o) const
  {
    return position == o.position && focal_point == o.focal_point && view_up == o.view_up && view_angle == o.view_angle;
  }
};

//! Where and how the brush meets the surface: what every tool's dabs share.
struct Brush
{
  float radius = 0.f;                   //!< world units
  float strength = 1.f;                 //!< 0..1
  int falloff = FALLOFF_SMOOTHSTEP;     //!< FALLOFF_*
  float spacing = 0.25f;                //!< dab spacing as a fraction of the radius
  int mirror_axis = -1;                 //!< 0, 1, 2 for x, y, z; -1 none
  int space = SPACE_OBJECT;             //!< SPACE_*: where the brush measures distance
  bool paint_backfaces = false;         //!< tangent, screen: also faces turned away from the brush
  bool has_camera = false;              //!< screen space, screen patterns: `camera` is given
  Camera camera;
  int side = 0;                         //!< two-sided surfaces: 0 the side the brush sees, 1 outside, 2 inside
  std::string stamp_file;               //!< brush image laid in the tangent plane
  std::shared_ptr<const Raster> stamp;  //!< its samples (loaded by the caller)
};

//! A solid texture or sampled pattern painted through (pattern paint).
struct Pattern
{
  int kind = PATTERN_NONE; //!< PATTERN_*
  int coord = PATTERN_COORD_POSITION;
  int matte = MATTE_SELF;
  int octaves = 4;
  std::array<float, 12> transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}; //!< 3x4, rows
  std::string file;                     //!< image or volume pattern, as the script names it
  std::shared_ptr<const Raster> raster; //!< its samples (loaded by the caller)
};

//! Paint, label, wash and dip: the paint equation on the channels.
struct PaintSettings
{
  int op = PAINT_OP_COPY;                    //!< PAINT_OP_*
  std::array<Float4, CHANNEL_COUNT> value{}; //!< per channel: rgb or x, and coverage in w
  std::array<float, CHANNEL_COUNT> alpha{};  //!< 0: channel untouched
  bool remover = false;                      //!< paint the underlying material back
  float specular_coefficient = -1.f;         //!< >= 0: polish / sandpaper the specular coefficient
  Pattern pattern;
  int spray_drops = 0;                       //!< screen space: droplets per dab (0: no spray)
  float spray_size = 0.f;                    //!< their radius on the surface, world units
  unsigned spray_seed = 0;
  std::vector<int> locked_labels;            //!< label channel: classes never overwritten
  int only_over_label = -1;                  //!< label channel: the one class overwritten (merge: the class merged); -1 any
  bool fill_diagonals = false;               //!< fill: texels that touch at a corner connect too (8 neighbours, not 4)
};

//! Smooth and blur: Laplacian or Taubin passes.
struct SmoothSettings
{
  int iterations = 1;               //!< passes per dab
  bool target_colour = false;       //!< colours instead of positions (blur: always)
  bool taubin = true;               //!< positions: lambda/mu pairs (no shrinking)
  float lambda = 0.5f, mu = -0.53f; //!< smoothing steps
  int edit_level = -1;              //!< positions: the level edited, finer levels follow; -1: the finest
};

//! Sculpt, inflate, flatten and grab: control points moved by the weights.
struct MoveSettings
{
  float amount = 0.f;  //!< sculpt, inflate: world units per dab; flatten: 0..1; grab: unused
  int edit_level = -1; //!< the level edited, finer levels follow; -1: the finest
};

//! Smear: the colours dragged along the path; nothing of its own.
struct SmearSettings
{
};

//! Equal as a stroke script writes them (loaded rasters are not compared).
bool operator==(const Brush& a, const Brush& b);
bool operator==(const Pattern& a, const Pattern& b);
bool operator==(const PaintSettings& a, const PaintSettings& b);
bool operator==(const SmoothSettings& a, const SmoothSettings& b);
bool operator==(const MoveSettings& a, const MoveSettings& b);
bool operator==(const SmearSettings& a, const SmearSettings& b);

//! The settings that belong to the stroke's tool (tool_settings_for() says which).
using ToolSettings = std::variant<PaintSettings, SmoothSettings, MoveSettings, SmearSettings>;

//! What a stroke script's stroke says: the tool, the path, the brush, and
//! the settings of that tool only.
struct Stroke
{
  Tool tool = Tool::Paint;
  std::vector<Vec3> points;    //!< the path, world coordinates
  std::vector<float> pressure; //!< per point, scales radius and strength; empty: 1
  Brush brush;
  ToolSettings settings;

  //! The tool's settings. \pre `settings` holds that kind (make_stroke()
  //! makes the tool's kind); std::bad_variant_access otherwise.
  PaintSettings& paint() { return std::get<PaintSettings>(settings); }
  const PaintSettings& paint() const { return std::get<PaintSettings>(settings); }
  SmoothSettings& smooth() { return std::get<SmoothSettings>(settings); }
  const SmoothSettings& smooth() const { return std::get<SmoothSettings>(settings); }
  MoveSettings& move() { return std::get<MoveSettings>(settings); }
  const MoveSettings& move() const { return std::get<MoveSettings>(settings); }
  //! Sets a geometry tool's edit level. \pre a geometry tool
  void set_edit_level(int level);
  //! Geometry tools: the level edited (-1: the finest); -1 for the others.
  int edit_level() const;
  //! A colour tool's pattern, or none.
  const Pattern* pattern() const;

  //! Same stroke as written in a script (loaded rasters are not compared).
  bool operator==(const Stroke& o) const;
  bool operator!=(const Stroke& o) const { return !(*this == o); }
};

//! A stroke of `tool` with that tool's default settings.
Stroke make_stroke(Tool tool);
//! \throw InputError unless the stroke's settings are of its tool's kind.
void check_settings(const Stroke& stroke);

//! What a stroke changes, which decides its undo layers, the side of a
//! two-sided surface it works on, and the part of the pipeline that runs it.
enum class ToolFamily
{
  Paint,        //!< paint, wash, dip: the paint equation on the channels
  Label,        //!< the label channel, which belongs to the surface, not to one side
  ColourFilter, //!< blur, smear, smooth with target_colour: filters of diffuse and specular
  Move,         //!< sculpt, inflate, flatten, grab: control points moved by weights
  Smooth        //!< smooth: Laplacian or Taubin passes over control points
};

ToolFamily tool_family(const Stroke& stroke);

//! A stroke-script error about one key of one stroke.
class StrokeKeyError : public InputError
{
public:
  StrokeKeyError(const std::string& message, std::string key, bool meaningless)
    : InputError(message), key_(std::move(key)), meaningless_(meaningless)
  {
  }
  const std::string& key() const { return key_; }
  //! The key is fine in itself but means nothing for the stroke's tool.
  bool meaningless() const { return meaningless_; }

private:
  std::string key_;
  bool meaningless_;
};

//! A brush kept as stroke keys (a window's or a setter API's current
//! settings) as one stroke: the JSON object without the keys that mean
//! nothing for its tool, e.g. a sculpt "amount" left over under a paint
//! tool. Other problems are left for parse_stroke_script() to report.
std::string drop_meaningless_keys(const std::string& stroke_object);

//! A stroke script: an optional atlas level and the strokes in order.
struct StrokeScript
{
  int level = -1; //!< -1: not given
  std::vector<Stroke> strokes;
};

//! Checks a stroke made in code (a window's brush, a setter API) exactly as
//! parse_stroke_script() checks a script's, and that its script form reads
//! back as the same stroke, so that a recording of it replays exactly.
//! \throw InputError naming the key, as parse_stroke_script() does.
void check_stroke(const Stroke& stroke);

//! Parses and checks a stroke script (docs/strokes.md). Nothing is returned
//! unless every stroke is valid.
//! \throw InputError naming the stroke (0-based) and key, e.g.
//! "stroke 2: \"radius\" must be a positive number".
StrokeScript parse_stroke_script(const std::string& json_text);

//! Reads and parses a stroke script file; relative pattern and stamp file
//! names are taken from the script's folder.
//! \throw IOError when the file cannot be read; InputError as above.
StrokeScript load_stroke_script(const std::string& path);

//! The script in the stroke-script format; parse_stroke_script() gives back
//! equal strokes (numbers are written so that they read back exactly).
std::string stroke_script_json(const StrokeScript& script);
//! One stroke as a JSON object of the same format.
std::string stroke_json(const Stroke& stroke);

//! Most dabs one stroke may have; parse_stroke_script() refuses longer ones.
constexpr std::size_t kMaxDabsPerStroke = 1000000;

//! Centres of the dabs of a stroke along its path, every spacing * radius
//! (pressure-scaled), the first point always included; with their pressure.
//! Empty for a stroke without a path (wash, dip).
struct DabSample
{
  Vec3 centre;
  float pressure;
  Vec3 heading{0.f, 0.f, 0.f}; //!< direction of the path there; zero for a single point
};
std::vector<DabSample> stroke_samples(const Stroke& stroke);

} // namespace meshpaint
