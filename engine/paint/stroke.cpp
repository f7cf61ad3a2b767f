#include "paint/stroke.h"

#include "paint/stroke_schema.h"

#include "core/errors.h"
#include "core/format.h"     // for meshpaint::excerpt
#include "core/input_file.h" // for meshpaint::read_input_file

#include <nlohmann/json.hpp> // for nlohmann::json

#include <algorithm> // for std::find, std::max
#include <array>     // for std::array
#include <cmath>   // for std::isfinite, std::sqrt
#include <filesystem> // for std::filesystem::path
#include <map>     // for std::map
#include <set>     // for std::set
#include <sstream> // for std::ostringstream

namespace meshpaint {
namespace {

using nlohmann::json;

//! Reads one stroke, with errors that name it and the key.
class StrokeReader
{
public:
  StrokeReader(const json& j, std::size_t index) : j_(j), where_("stroke " + std::to_string(index) + ": ") {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const
  {
    throw StrokeKeyError(where_ + "\"" + excerpt(key) + "\" " + what, key, what.rfind("has no meaning", 0) == 0);
  }

  bool has(const std::string& key) const { return j_.contains(key); }

  double number(const std::string& key, double fallback, double min, double max) const
  {
    if (!has(key))
      return fallback;
    const json& v = j_.at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < min || v.get<double>() > max)
      fail(key, "must be a number from " + text(min) + " to " + text(max));
    return v.get<double>();
  }

  //! A number key within the schema's range.
  double number(const StrokeKey& key, double fallback) const { return number(key.name, fallback, key.min, key.max); }
  //! The same, with the schema's default.
  double number(const StrokeKey& key) const { return number(key, std::stod(key.fallback)); }

  //! A word key: one of the schema's names.
  std::string word(const StrokeKey& key, const std::string& fallback) const
  {
    return word(key.name, fallback, key_names(key));
  }

  //! The member value of a word key's name (the fallback's when absent).
  int value(const StrokeKey& key, const std::string& fallback) const { return value_of(key, word(key, fallback)); }

  //! The key is given although the schema says it means nothing for `tool`.
  bool meaningless(const StrokeKey& key, Tool tool) const { return has(key.name) && !applies_to(key, tool); }

  std::string word(const std::string& key, const std::string& fallback,
                   const std::vector<std::string>& allowed) const
  {
    if (!has(key))
      return fallback;
    const json& v = j_.at(key);
    if (v.is_string())
      for (const std::string& a : allowed)
        if (v.get<std::string>() == a)
          return a;
    fail(key, "must be one of " + join_names(allowed));
  }

  std::vector<Vec3> points(const std::string& key) const
  {
    std::vector<Vec3> out;
    const json& v = j_.at(key);
    if (!v.is_array())
      fail(key, "must be a list of [x, y, z] points");
    for (const json& p : v) {
      if (!p.is_array() || p.size() != 3)
        fail(key, "must be a list of [x, y, z] points");
      Vec3 q;
      for (int k = 0; k < 3; ++k) {
        if (!p[k].is_number() || !std::isfinite(p[k].get<double>()))
          fail(key, "must hold finite numbers");
        q[k] = p[k].get<float>();
      }
      out.push_back(q);
    }
    return out;
  }

  const json& at(const std::string& key) const { return j_.at(key); }
  const std::string& where() const { return where_; }

  static std::string text(double v)
  {
    std::ostringstream s;
    s << v;
    return s.str();
  }

private:
  const json& j_;
  std::string where_;
};

//! The channel of that name, or -1.
int channel_named(const std::string& name)
{
  const std::vector<std::string>& names = channel_names();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : int(it - names.begin());
}

//! "channels": {"diffuse": [r, g, b] or [r, g, b, coverage], "roughness": v, "label": id, ...}
//! "alphas": {"diffuse": a, ...} (default 1 for every channel given)
void read_channels(const StrokeReader& r, Stroke& s)
{
  if (!r.has("channels"))
    return;
  const json& ch = r.at("channels");
  if (!ch.is_object())
    r.fail("channels", "must be an object such as {\"diffuse\": [1, 0, 0]}");
  for (const auto& [name, v] : ch.items()) {
    const int c = channel_named(name);
    if (c < 0)
      r.fail("channels", "has an unknown channel \"" + excerpt(name) + "\" (" + join_names(channel_names()) + ")");
    Float4 value{0.f, 0.f, 0.f, 1.f};
    if (c == CHANNEL_DIFFUSE || c == CHANNEL_SPECULAR) {
      if (!v.is_array() || (v.size() != 3 && v.size() != 4))
        r.fail("channels", "\"" + name + "\" must be [r, g, b] or [r, g, b, coverage]");
      for (std::size_t k = 0; k < v.size(); ++k) {
        if (!v[k].is_number() || v[k].get<double>() < 0 || v[k].get<double>() > 1)
          r.fail("channels", "\"" + name + "\" components must be numbers from 0 to 1");
        value[k] = v[k].get<float>();
      }
    } else if (c == CHANNEL_LABEL) {
      if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > (1 << 24))
        r.fail("channels", "\"label\" must be an integer class id from 0 to 16777216");
      value = {v.get<float>(), v.get<float>(), v.get<float>(), 1.f};
    } else {
      const bool bounded = c != CHANNEL_DISPLACEMENT;
      if (!v.is_number() || !std::isfinite(v.get<double>()) || (bounded && (v.get<double>() < 0 || v.get<double>() > 1)))
        r.fail("channels", "\"" + name + "\" must be a number" + (bounded ? " from 0 to 1" : ""));
      value = {v.get<float>(), v.get<float>(), v.get<float>(), 1.f};
    }
    s.paint().value[c] = value;
    s.paint().alpha[c] = 1.f;
  }
  if (r.has("alphas")) {
    const json& al = r.at("alphas");
    if (!al.is_object())
      r.fail("alphas", "must be an object such as {\"diffuse\": 0.5}");
    for (const auto& [name, v] : al.items()) {
      const int c = channel_named(name);
      if (c < 0 || !ch.contains(name))
        r.fail("alphas", "names \"" + name + "\", which \"channels\" does not paint");
      if (!v.is_number() || v.get<double>() < 0 || v.get<double>() > 1)
        r.fail("alphas", "\"" + name + "\" must be a number from 0 to 1");
      s.paint().alpha[std::size_t(c)] = v.get<float>();
    }
  }
}

//! "pattern": {"type": "noise"|"turbulence"|"marble"|"bath", "coord": "position"|"uv",
//! "matte": "self"|"opaque", "scale": s, "octaves": n, "transform": [[...4], [...4], [...4]]}
void read_pattern(const StrokeReader& r, Stroke& s)
{
  const json& p = r.at("pattern");
  if (!p.is_object())
    r.fail("pattern", "must be an object such as {\"type\": \"marble\", \"scale\": 4}");
  for (const auto& item : p.items()) {
    const auto& keys = pattern_keys();
    if (std::none_of(keys.begin(), keys.end(), [&](const StrokeKey& k) { return item.key() == k.name; }))
      r.fail("pattern", "has an unknown key \"" + excerpt(item.key()) + "\" (" + key_list(keys) + ")");
  }
  // A word of the pattern object: its member value (the fallback's when absent).
  const auto value = [&](const char* name, const std::string& fallback) {
    const StrokeKey& key = pattern_key(name);
    if (!p.contains(name))
      return value_of(key, fallback);
    if (p[name].is_string())
      for (const KeyName& n : key.names)
        if (p[name].get<std::string>() == n.name)
          return n.value;
    r.fail("pattern", std::string("\"") + name + "\" must be one of " + name_list(key));
  };
  if (!p.contains("type"))
    r.fail("pattern", "needs a \"type\" (" + name_list(pattern_key("type")) + ")");
  s.paint().pattern.kind = value("type", "");
  const bool sampled = s.paint().pattern.kind == PATTERN_IMAGE || s.paint().pattern.kind == PATTERN_VOLUME;
  if (sampled != p.contains("file"))
    r.fail("pattern", sampled ? "of type image or volume needs a \"file\"" : "\"file\" belongs to image and volume patterns");
  if (sampled) {
    if (!p["file"].is_string() || p["file"].get<std::string>().empty())
      r.fail("pattern", "\"file\" must be a file name");
    s.paint().pattern.file = p["file"].get<std::string>();
  }
  s.paint().pattern.coord = value("coord", pattern_key("coord").fallback);
  s.paint().pattern.matte = value("matte", pattern_key("matte").fallback);
  double scale = 1.0;
  if (p.contains("scale")) {
    if (!p["scale"].is_number() || !(p["scale"].get<double>() > 0) || !std::isfinite(p["scale"].get<double>()))
      r.fail("pattern", "\"scale\" must be a positive number");
    scale = p["scale"].get<double>();
  }
  if (p.contains("octaves")) {
    const StrokeKey& octaves = pattern_key("octaves");
    if (!p["octaves"].is_number_integer() || p["octaves"].get<int>() < octaves.min || p["octaves"].get<int>() > octaves.max)
      r.fail("pattern", "\"octaves\" must be an integer from " + StrokeReader::text(octaves.min) + " to " +
                          StrokeReader::text(octaves.max));
    s.paint().pattern.octaves = p["octaves"].get<int>();
  }
  if (p.contains("transform")) {
    const json& t = p["transform"];
    if (!t.is_array() || t.size() != 3)
      r.fail("pattern", "\"transform\" must be three rows of four numbers (a 3x4 matrix)");
    for (int row = 0; row < 3; ++row) {
      if (!t[row].is_array() || t[row].size() != 4)
        r.fail("pattern", "\"transform\" must be three rows of four numbers (a 3x4 matrix)");
      for (int col = 0; col < 4; ++col) {
        if (!t[row][col].is_number() || !std::isfinite(t[row][col].get<double>()))
          r.fail("pattern", "\"transform\" must hold finite numbers");
        s.paint().pattern.transform[std::size_t(row * 4 + col)] = t[row][col].get<float>();
      }
    }
  }
  for (float& m : s.paint().pattern.transform) // the scale applies after the transform
    m = float(m * scale);
}

//! "locked_labels": [ids], "only_over_label": id: which classes a stroke
//! that paints the label channel may overwrite (a merge: the class merged);
//! "connect": how a fill's region grows.
void read_label_guards(const StrokeReader& r, Stroke& s, const std::string& tool)
{
  const auto* p = std::get_if<PaintSettings>(&s.settings);
  for (const char* key : {"locked_labels", "only_over_label"})
    if (r.has(key) && !(p && p->alpha[CHANNEL_LABEL] > 0.f))
      r.fail(key, "has no meaning for a " + tool + " stroke that does not paint the label channel");
  const auto id = [](const json& v) {
    return v.is_number_integer() && v.get<long long>() >= 0 && v.get<long long>() <= (1 << 24);
  };
  if (r.has("locked_labels")) {
    const json& v = r.at("locked_labels");
    if (!v.is_array() || v.size() > 4096)
      r.fail("locked_labels", "must be a list of at most 4096 class ids");
    for (const json& e : v) {
      if (!id(e))
        r.fail("locked_labels", "must hold integer class ids from 0 to 16777216");
      s.paint().locked_labels.push_back(e.get<int>());
    }
  }
  if (r.has("only_over_label")) {
    if (!id(r.at("only_over_label")))
      r.fail("only_over_label", "must be an integer class id from 0 to 16777216 (0: unlabelled)");
    s.paint().only_over_label = r.at("only_over_label").get<int>();
  }
  if (r.has("connect")) {
    if (s.tool != Tool::Fill)
      r.fail("connect", "has no meaning for a " + tool + " stroke: only a fill connects texels");
    s.paint().fill_diagonals = r.value(stroke_key("connect"), stroke_key("connect").fallback) == 1;
  }
  if (s.tool == Tool::Merge && !r.has("only_over_label"))
    r.fail("only_over_label", "is required for a merge: the class whose texels become \"channels\" {\"label\": id}");
}

//! "camera": {"position": [x, y, z], "focal_point": [...], "view_up": [...], "view_angle": degrees}
Camera read_camera(const StrokeReader& r)
{
  const json& c = r.at("camera");
  const char* const shape = "must be {\"position\": [x, y, z], \"focal_point\": [x, y, z], \"view_up\": [x, y, z], "
                            "\"view_angle\": degrees}";
  if (!c.is_object())
    r.fail("camera", shape);
  for (const auto& item : c.items())
    if (item.key() != "position" && item.key() != "focal_point" && item.key() != "view_up" &&
        item.key() != "view_angle")
      r.fail("camera", "has an unknown key \"" + excerpt(item.key()) + "\" (position, focal_point, view_up, view_angle)");
  Camera cam;
  for (const auto& [key, target] : {std::pair<const char*, Vec3*>{"position", &cam.position},
                                    {"focal_point", &cam.focal_point}, {"view_up", &cam.view_up}}) {
    if (!c.contains(key))
      r.fail("camera", shape);
    const json& v = c.at(key);
    if (!v.is_array() || v.size() != 3)
      r.fail("camera", std::string("\"") + key + "\" must be [x, y, z]");
    for (int k = 0; k < 3; ++k) {
      if (!v[k].is_number() || !std::isfinite(v[k].get<double>()))
        r.fail("camera", std::string("\"") + key + "\" must hold finite numbers");
      (*target)[k] = v[k].get<float>();
    }
  }
  if (c.contains("view_angle")) {
    const json& a = c.at("view_angle");
    if (!a.is_number() || !(a.get<double>() > 0) || !(a.get<double>() < 180))
      r.fail("camera", "\"view_angle\" must be a number of degrees between 0 and 180");
    cam.view_angle = a.get<float>();
  }
  const Vec3 d{cam.focal_point[0] - cam.position[0], cam.focal_point[1] - cam.position[1],
               cam.focal_point[2] - cam.position[2]};
  const Vec3 x{d[1] * cam.view_up[2] - d[2] * cam.view_up[1], d[2] * cam.view_up[0] - d[0] * cam.view_up[2],
               d[0] * cam.view_up[1] - d[1] * cam.view_up[0]};
  if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 0.f))
    r.fail("camera", "\"focal_point\" must differ from \"position\"");
  if (!(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] > 0.f))
    r.fail("camera", "\"view_up\" must not be parallel to the direction of view");
  return cam;
}

//! "space", "camera", "backfaces" and "spray": how the brush meets the surface.
void read_space(const StrokeReader& r, Stroke& s, const std::string& tool, bool everywhere)
{
  const StrokeKey& space = stroke_key("space");
  s.brush.space = r.value(space, space.fallback);
  if (everywhere && r.has("space"))
    r.fail("space", "has no meaning for a " + tool + ", which covers everything at once");
  const bool screen =
    s.brush.space == SPACE_SCREEN || (s.pattern() && s.pattern()->coord == PATTERN_COORD_SCREEN);
  if (screen && !r.has("camera"))
    r.fail("camera", "is required for a screen-space brush or pattern: the view it is drawn in");
  if (r.has("camera")) {
    if (!screen)
      r.fail("camera", "has no meaning unless \"space\" is \"screen\" or the pattern's \"coord\" is \"screen\"");
    s.brush.camera = read_camera(r);
    s.brush.has_camera = true;
  }
  if (r.has("backfaces")) {
    if (s.brush.space != SPACE_SCREEN && s.brush.space != SPACE_TANGENT)
      r.fail("backfaces", "has no meaning unless \"space\" is \"screen\" or \"tangent\"");
    s.brush.paint_backfaces = r.value(stroke_key("backfaces"), stroke_key("backfaces").fallback) == 1;
  }
  if (r.has("side")) {
    const ToolFamily family = tool_family(s);
    const bool colours = family == ToolFamily::Paint || family == ToolFamily::ColourFilter;
    if (!colours)
      r.fail("side", "has no meaning for a " + tool + " stroke: only colours and roughness have two sides");
    s.brush.side = r.value(stroke_key("side"), stroke_key("side").fallback);
  }
  if (r.has("spray")) {
    if (s.brush.space != SPACE_SCREEN || !applies_to(stroke_key("spray"), s.tool))
      r.fail("spray", "has no meaning unless a paint or label stroke is in screen space");
    const json& sp = r.at("spray");
    if (!sp.is_object())
      r.fail("spray", "must be {\"drops\": n, \"size\": radius, \"seed\": k}");
    for (const auto& item : sp.items())
      if (item.key() != "drops" && item.key() != "size" && item.key() != "seed")
        r.fail("spray", "has an unknown key \"" + excerpt(item.key()) + "\" (drops, size, seed)");
    if (!sp.contains("drops") || !sp["drops"].is_number_integer() || sp["drops"].get<long long>() < 1 ||
        sp["drops"].get<long long>() > 4096)
      r.fail("spray", "\"drops\" must be an integer from 1 to 4096 (droplets per dab)");
    if (!sp.contains("size") || !sp["size"].is_number() || !(sp["size"].get<double>() > 0) ||
        !std::isfinite(sp["size"].get<double>()))
      r.fail("spray", "\"size\" must be a positive number (a droplet's radius in world units)");
    if (sp.contains("seed") && (!sp["seed"].is_number_integer() || sp["seed"].get<long long>() < 0 ||
                                sp["seed"].get<long long>() > 4294967295LL))
      r.fail("spray", "\"seed\" must be an integer from 0 to 4294967295");
    s.paint().spray_drops = sp["drops"].get<int>();
    s.paint().spray_size = sp["size"].get<float>();
    s.paint().spray_seed = sp.contains("seed") ? sp["seed"].get<unsigned>() : 0u;
  }
}

Stroke read_stroke(const json& j, std::size_t index)
{
  if (!j.is_object())
    throw InputError("stroke " + std::to_string(index) + ": must be an object");
  const StrokeReader r(j, index);
  for (const auto& item : j.items()) {
    const auto& keys = stroke_keys();
    if (std::none_of(keys.begin(), keys.end(), [&](const StrokeKey& k) { return item.key() == k.name; }))
      r.fail(item.key(), "is not a stroke key (" + key_list(keys) + ")");
  }
  const StrokeKey& tool_key = stroke_key("tool");
  std::string tool = r.word(tool_key, tool_key.fallback);
  Stroke s = make_stroke(tool_named(tool));
  // The paint equation's filtering ops are brushes of their own: "op":
  // "blur" filters the colours under the brush, "op": "smear" drags them.
  if (s.tool == Tool::Paint && r.has("op") && r.at("op").is_string() &&
      (r.at("op").get<std::string>() == "blur" || r.at("op").get<std::string>() == "smear")) {
    tool = r.at("op").get<std::string>();
    s = make_stroke(tool_named(tool));
    if (r.has("channels"))
      r.fail("channels", "has no meaning for op " + tool + ", which moves the colours already there");
  }
  const bool labels = s.tool == Tool::Label || s.tool == Tool::Fill || s.tool == Tool::Merge;
  const bool paints = applies_to(stroke_key("channels"), s.tool);
  const bool everywhere = covers_everything(s.tool);
  const bool moves = applies_to(stroke_key("amount"), s.tool);
  const bool smooths = applies_to(stroke_key("iterations"), s.tool);
  for (const char* key : {"channels", "alphas"})
    if (r.meaningless(stroke_key(key), s.tool))
      r.fail(key, std::string("has no meaning for a ") + tool + " stroke");
  // A blur or smear stroke may name itself as its op, and nothing else.
  const bool filter_op = s.tool == Tool::Blur || s.tool == Tool::Smear;
  if (!paints && r.has("op") && !(filter_op && r.at("op").is_string() && r.at("op").get<std::string>() == tool))
    r.fail("op", "has no meaning for a " + tool + " stroke");
  for (const char* key : {"amount", "iterations", "method", "lambda", "mu", "target"})
    if (r.meaningless(stroke_key(key), s.tool))
      r.fail(key, std::string("has no meaning for a ") + tool + " stroke");
  if (moves) {
    const bool flatten = s.tool == Tool::Flatten;
    // flatten moves a fraction of the way to the plane; the others world units
    s.move().amount = float(flatten ? r.number("amount", 0.5, 0.0, 1.0) : r.number(stroke_key("amount"), 0.0));
    if (!flatten && !r.has("amount"))
      r.fail("amount", "is required: how far a dab moves the surface, in world units");
  }
  if (smooths) {
    const StrokeKey& iterations = stroke_key("iterations");
    s.smooth().iterations = int(r.number(iterations));
    if (r.has("iterations") && !r.at("iterations").is_number_integer())
      r.fail("iterations", "must be an integer from " + StrokeReader::text(iterations.min) + " to " +
                             StrokeReader::text(iterations.max));
    const StrokeKey& target = stroke_key("target");
    s.smooth().target_colour = s.tool == Tool::Blur || r.value(target, target.fallback) == 1;
    s.smooth().taubin = r.value(stroke_key("method"), s.smooth().target_colour ? "laplacian" : "taubin") == 1;
    if (s.smooth().taubin && s.smooth().target_colour)
      r.fail("method", "taubin is for positions; colours are smoothed with laplacian");
    s.smooth().lambda = float(r.number(stroke_key("lambda")));
    s.smooth().mu = float(r.number(stroke_key("mu")));
    if (!s.smooth().target_colour && r.has("mu") && !s.smooth().taubin)
      r.fail("mu", "belongs to Taubin smoothing (\"method\": \"taubin\")");
    if (s.smooth().taubin && !(-s.smooth().mu > s.smooth().lambda))
      r.fail("mu", "must be more negative than -lambda for Taubin smoothing (e.g. lambda 0.5, mu -0.53)");
  }
  if (r.has("edit_level")) {
    const StrokeKey& edit_level = stroke_key("edit_level");
    const bool shapes = tool_family(s) == ToolFamily::Move || tool_family(s) == ToolFamily::Smooth;
    if (!shapes)
      r.fail("edit_level", "has no meaning for a " + tool + " stroke, which does not move the surface");
    if (!r.at("edit_level").is_number_integer() || r.at("edit_level").get<long long>() < edit_level.min ||
        r.at("edit_level").get<long long>() > edit_level.max)
      r.fail("edit_level", "must be an integer from " + StrokeReader::text(edit_level.min) + " to " +
                             StrokeReader::text(edit_level.max));
    s.set_edit_level(r.at("edit_level").get<int>());
  }
  s.brush.strength = float(r.number(stroke_key("strength")));
  s.brush.falloff = r.value(stroke_key("falloff"), stroke_key("falloff").fallback);
  if (paints) {
    // "blur" and "smear" on a label, wash or dip stroke have always meant copy.
    const int op = r.value(stroke_key("op"), stroke_key("op").fallback);
    s.paint().op = op < 0 ? PAINT_OP_COPY : op;
  }
  s.brush.spacing = float(r.number(stroke_key("spacing")));
  if (r.has("mirror") && s.tool == Tool::Grab)
    r.fail("mirror", "has no meaning for a grab stroke, which pulls one region");
  if (r.has("mirror"))
    s.brush.mirror_axis = r.value(stroke_key("mirror"), "x");
  read_channels(r, s);

  if (everywhere) {
    for (const char* key : {"points", "radius", "pressure", "mirror", "spacing", "falloff", "stroke"})
      if (r.meaningless(stroke_key(key), s.tool))
        r.fail(key, "has no meaning for a " + tool + ", which covers everything at once");
  } else {
    if (!r.has("points"))
      r.fail("points", "is required: the path of the stroke as [[x, y, z], ...]");
    s.points = r.points("points");
    if (s.points.empty())
      r.fail("points", "is empty: a stroke needs at least one point");
    if (s.tool == Tool::Fill) {
      if (s.points.size() != 1)
        r.fail("points", "of a fill must be one point: where the region to fill is");
      for (const char* key : {"mirror", "pressure", "stroke", "space"})
        if (r.has(key))
          r.fail(key, "has no meaning for a fill, which fills the region at one point");
    }
    if (!r.has("radius"))
      r.fail("radius", "is required (world units)");
    s.brush.radius = float(r.number(stroke_key("radius"), 0.0));
    if (r.has("pressure")) {
      const json& p = r.at("pressure");
      if (!p.is_array() || p.size() != s.points.size())
        r.fail("pressure", "must be a list of numbers, one per point");
      for (const json& v : p) {
        if (!v.is_number() || v.get<double>() < 0 || v.get<double>() > 1)
          r.fail("pressure", "values must be numbers from 0 to 1");
        s.pressure.push_back(v.get<float>());
      }
    }
  }
  if (!everywhere) {
    // A path a million dabs long is a mistake, not a stroke: say so rather
    // than run for hours (spacing shrinks with pressure down to 1/20).
    double length = 0;
    for (std::size_t k = 1; k < s.points.size(); ++k) {
      double d2 = 0;
      for (int a = 0; a < 3; ++a)
        d2 += double(s.points[k][a] - s.points[k - 1][a]) * double(s.points[k][a] - s.points[k - 1][a]);
      length += std::sqrt(d2);
    }
    const double step = double(s.brush.spacing) * double(s.brush.radius) * (s.pressure.empty() ? 1.0 : 0.05);
    if (length / step > double(kMaxDabsPerStroke))
      r.fail("spacing", "x radius is too small for the path: more than " + std::to_string(kMaxDabsPerStroke) +
                          " dabs in one stroke");
  }
  if (r.has("stroke")) {
    // rubberband: a straight line from the first point to the last;
    // rubberstamp: the first point only; interpolated: every point.
    const std::string kind = r.word(stroke_key("stroke"), stroke_key("stroke").fallback);
    if (kind == "rubberband" && s.points.size() > 2) {
      s.points = {s.points.front(), s.points.back()};
      if (!s.pressure.empty())
        s.pressure = {s.pressure.front(), s.pressure.back()};
    } else if (kind == "rubberstamp") {
      s.points.resize(1);
      if (!s.pressure.empty())
        s.pressure.resize(1);
    }
  }
  if (r.has("stamp")) {
    if (!applies_to(stroke_key("stamp"), s.tool))
      r.fail("stamp", "has no meaning for a " + tool + " stroke");
    if (!r.at("stamp").is_string() || r.at("stamp").get<std::string>().empty())
      r.fail("stamp", "must be the file name of a brush image");
    s.brush.stamp_file = r.at("stamp").get<std::string>();
  }
  if (r.meaningless(stroke_key("pattern"), s.tool))
    r.fail("pattern", "has no meaning for a " + tool + " stroke");
  if (r.has("pattern"))
    read_pattern(r, s);
  read_space(r, s, tool, everywhere);
  if (s.tool == Tool::Dip && s.paint().pattern.kind == PATTERN_NONE)
    r.fail("pattern", "is required for a dip: the 3D matte to dip through, e.g. {\"type\": \"bath\"}");
  if (r.meaningless(stroke_key("mode"), s.tool))
    r.fail("mode", "has no meaning for a " + tool + " stroke");
  const std::string mode = r.word(stroke_key("mode"), "");
  if (!r.has("mode") && r.has("coefficient"))
    r.fail("coefficient", "belongs to the polish and sandpaper modes");
  if (mode == "material") {
    for (const char* c : {"diffuse", "specular", "roughness"})
      if (!r.has("channels") || !r.at("channels").contains(c))
        r.fail("channels", std::string("of full material paint must give diffuse, specular and roughness; \"") + c +
                             "\" is missing");
  } else if (mode == "remover") {
    if (r.has("channels"))
      r.fail("channels", "has no meaning for the remover, which paints the underlying material back");
    s.paint().remover = true;
    for (const int c : {CHANNEL_DIFFUSE, CHANNEL_SPECULAR, CHANNEL_ROUGHNESS, CHANNEL_DISPLACEMENT})
      s.paint().alpha[c] = 1.f;
  } else if (mode == "dye") {
    if (!r.has("channels"))
      r.fail("channels", "of dye paint must give diffuse or specular");
    for (const auto& item : r.at("channels").items())
      if (item.key() != "diffuse" && item.key() != "specular")
        r.fail("channels", "of dye paint may only be diffuse and specular, not \"" + excerpt(item.key()) + "\"");
  } else if (mode == "polish" || mode == "sandpaper") {
    if (r.has("channels"))
      for (const auto& item : r.at("channels").items())
        if (item.key() != "roughness")
          r.fail("channels", "of " + mode + " paint may only be roughness, not \"" + excerpt(item.key()) + "\"");
    const bool polish = mode == "polish";
    if (s.paint().alpha[CHANNEL_ROUGHNESS] == 0.f) {
      const float rough = polish ? 0.1f : 0.9f;
      s.paint().value[CHANNEL_ROUGHNESS] = {rough, rough, rough, 1.f};
      s.paint().alpha[CHANNEL_ROUGHNESS] = 1.f;
    }
    s.paint().specular_coefficient = float(r.number(stroke_key("coefficient"), polish ? 0.9 : 0.05));
    s.paint().value[CHANNEL_SPECULAR] = {0.f, 0.f, 0.f, 1.f};
    s.paint().alpha[CHANNEL_SPECULAR] = 1.f;
  }
  const bool has_paint = paints && (r.has("channels") || s.paint().remover || s.paint().specular_coefficient >= 0.f);
  if (labels) {
    if (!r.has("channels") || r.at("channels").size() != 1 || !r.at("channels").contains("label"))
      r.fail("channels", "of a " + tool + " stroke must be exactly {\"label\": id}");
  } else if (paints && !has_paint) {
    r.fail("channels", "is required: what to paint, e.g. {\"diffuse\": [1, 0, 0]}");
  }
  read_label_guards(r, s, tool);
  return s;
}

} // namespace

const char* tool_name(Tool tool) { return name_of(stroke_key("tool"), int(tool)); }

Tool tool_named(const std::string& name)
{
  for (const KeyName& n : stroke_key("tool").names)
    if (name == n.name)
      return Tool(n.value);
  throw InputError("'" + excerpt(name) + "' is not a tool");
}

void check_stroke(const Stroke& stroke)
{
  const Stroke back = read_stroke(json::parse(stroke_json(stroke)), 0);
  if (back != stroke)
    throw InputError("stroke 0: does not read back as itself from its script form " + stroke_json(stroke));
}

ToolFamily tool_family(const Stroke& stroke)
{
  switch (stroke.tool) {
  case Tool::Label:
  case Tool::Fill:
  case Tool::Merge: return ToolFamily::Label;
  case Tool::Blur:
  case Tool::Smear: return ToolFamily::ColourFilter;
  case Tool::Smooth: {
    const auto* smooth = std::get_if<SmoothSettings>(&stroke.settings);
    return smooth && smooth->target_colour ? ToolFamily::ColourFilter : ToolFamily::Smooth;
  }
  case Tool::Sculpt:
  case Tool::Inflate:
  case Tool::Flatten:
  case Tool::Grab: return ToolFamily::Move;
  default: return ToolFamily::Paint;
  }
}

// What a script says of each part; loaded rasters are not compared.
bool operator==(const Brush& a, const Brush& b)
{
  return a.radius == b.radius && a.strength == b.strength && a.falloff == b.falloff && a.spacing == b.spacing &&
         a.mirror_axis == b.mirror_axis && a.space == b.space && a.paint_backfaces == b.paint_backfaces &&
         a.has_camera == b.has_camera && (!a.has_camera || a.camera == b.camera) && a.side == b.side &&
         a.stamp_file == b.stamp_file;
}

bool operator==(const Pattern& a, const Pattern& b)
{
  return a.kind == b.kind && a.coord == b.coord && a.matte == b.matte && a.octaves == b.octaves &&
         a.transform == b.transform && a.file == b.file;
}

bool operator==(const PaintSettings& a, const PaintSettings& b)
{
  return a.op == b.op && a.value == b.value && a.alpha == b.alpha && a.remover == b.remover &&
         a.specular_coefficient == b.specular_coefficient && a.pattern == b.pattern && a.spray_drops == b.spray_drops &&
         a.spray_size == b.spray_size && a.spray_seed == b.spray_seed && a.locked_labels == b.locked_labels &&
         a.only_over_label == b.only_over_label && a.fill_diagonals == b.fill_diagonals;
}

bool operator==(const SmoothSettings& a, const SmoothSettings& b)
{
  return a.iterations == b.iterations && a.target_colour == b.target_colour && a.taubin == b.taubin &&
         a.lambda == b.lambda && a.mu == b.mu && a.edit_level == b.edit_level;
}

bool operator==(const MoveSettings& a, const MoveSettings& b)
{
  return a.amount == b.amount && a.edit_level == b.edit_level;
}

bool operator==(const SmearSettings&, const SmearSettings&) { return true; }

bool Stroke::operator==(const Stroke& o) const
{
  return tool == o.tool && points == o.points && pressure == o.pressure && brush == o.brush && settings == o.settings;
}

Stroke make_stroke(Tool tool)
{
  Stroke s;
  s.tool = tool;
  switch (tool) {
  case Tool::Smooth:
  case Tool::Blur:
    s.settings = SmoothSettings();
    s.smooth().target_colour = tool == Tool::Blur; // colours take Laplacian passes
    s.smooth().taubin = tool != Tool::Blur;
    break;
  case Tool::Sculpt:
  case Tool::Inflate:
  case Tool::Flatten:
  case Tool::Grab: s.settings = MoveSettings(); break;
  case Tool::Smear: s.settings = SmearSettings(); break;
  default: s.settings = PaintSettings(); break;
  }
  return s;
}

void Stroke::set_edit_level(int level)
{
  if (auto* m = std::get_if<SmoothSettings>(&settings))
    m->edit_level = level;
  else
    move().edit_level = level;
}

void check_settings(const Stroke& stroke)
{
  if (stroke.settings.index() != make_stroke(stroke.tool).settings.index())
    throw InputError(std::string("a ") + tool_name(stroke.tool) + " stroke carries another tool's settings");
}

int Stroke::edit_level() const
{
  if (const auto* m = std::get_if<MoveSettings>(&settings))
    return m->edit_level;
  if (const auto* m = std::get_if<SmoothSettings>(&settings))
    return m->target_colour ? -1 : m->edit_level;
  return -1;
}

const Pattern* Stroke::pattern() const
{
  const auto* p = std::get_if<PaintSettings>(&settings);
  return p ? &p->pattern : nullptr;
}

StrokeScript parse_stroke_script(const std::string& text)
{
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    // (or out_of_range.406 for a number too large for a double)
    const std::string what = e.what();
    const std::size_t at = what.find("] ");
    throw InputError("stroke script is not valid JSON: " +
                     excerpt(at == std::string::npos ? what : what.substr(at + 2), kMessageChars));
  }
  if (!j.is_object())
    throw InputError("stroke script must be a JSON object {\"strokes\": [...]}");
  for (const auto& item : j.items())
    if (item.key() != "level" && item.key() != "strokes")
      throw InputError("stroke script: \"" + excerpt(item.key()) + "\" is not a script key (level, strokes)");
  StrokeScript script;
  if (j.contains("level")) {
    if (!j["level"].is_number_integer() || j["level"].get<long long>() < 1 || j["level"].get<long long>() > 12)
      throw InputError("stroke script: \"level\" must be an integer from 1 to 12");
    script.level = j["level"].get<int>();
  }
  if (!j.contains("strokes") || !j["strokes"].is_array())
    throw InputError("stroke script: \"strokes\" must be a list of strokes");
  for (std::size_t k = 0; k < j["strokes"].size(); ++k)
    script.strokes.push_back(read_stroke(j["strokes"][k], k));
  return script;
}

std::string drop_meaningless_keys(const std::string& stroke_object)
{
  json stroke;
  try {
    stroke = json::parse(stroke_object);
  } catch (const json::parse_error&) {
    return stroke_object;
  }
  if (stroke.is_object()) {
    // The schema says which keys a tool reads; the rest belong to other tools.
    Tool tool = Tool::Paint;
    const std::vector<std::string> tools = key_names(stroke_key("tool"));
    if (stroke.contains("tool") && stroke["tool"].is_string() &&
        std::count(tools.begin(), tools.end(), stroke["tool"].get<std::string>()))
      tool = tool_named(stroke["tool"].get<std::string>());
    else if (stroke.contains("tool"))
      return stroke.dump(); // parse_stroke_script() says what is wrong
    if (tool == Tool::Paint && stroke.contains("op") && (stroke["op"] == "blur" || stroke["op"] == "smear"))
      tool = tool_named(stroke["op"].get<std::string>());
    for (const StrokeKey& key : stroke_keys())
      if (!applies_to(key, tool))
        stroke.erase(key.name);
  }
  // Whether a key means something may depend on others ("camera" on "space"):
  // the parser says, one key at a time.
  for (std::size_t tries = 0; stroke.is_object() && tries <= stroke.size(); ++tries) {
    try {
      read_stroke(stroke, 0);
      break;
    } catch (const StrokeKeyError& e) {
      if (!e.meaningless() || !stroke.contains(e.key()))
        break;
      stroke.erase(e.key());
    } catch (const InputError&) {
      break;
    }
  }
  return stroke.dump();
}

StrokeScript load_stroke_script(const std::string& path)
{
  const std::string text = read_input_file(path, kMaxStrokeScriptBytes, "stroke script");
  StrokeScript script;
  try {
    script = parse_stroke_script(text);
  } catch (const InputError& e) {
    throw InputError("'" + path + "': " + e.what());
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  for (Stroke& s : script.strokes)
    for (std::string* file : {s.pattern() ? &s.paint().pattern.file : nullptr, &s.brush.stamp_file})
      if (file && !file->empty() && std::filesystem::path(*file).is_relative())
        *file = (dir / *file).string();
  return script;
}

std::vector<DabSample> stroke_samples(const Stroke& s)
{
  const auto pressure_at = [&](std::size_t k) { return s.pressure.empty() ? 1.f : s.pressure[k]; };
  // Spacing follows the pressure-scaled radius; never below a tiny step.
  const auto step = [&](float pressure) { return s.brush.spacing * s.brush.radius * std::max(pressure, 0.05f); };
  if (s.points.empty()) // wash and dip have no path
    return {};
  if (!(step(0.05f) > 0.f))
    return {{s.points[0], pressure_at(0)}};
  std::vector<DabSample> out{{s.points[0], pressure_at(0)}};
  if (s.points.size() > 1)
    for (int k = 0; k < 3; ++k)
      out[0].heading[k] = s.points[1][k] - s.points[0][k];
  float since = 0.f; // path length since the last dab
  for (std::size_t k = 1; k < s.points.size(); ++k) {
    const Vec3 &a = s.points[k - 1], &b = s.points[k];
    const float len = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                                (b[2] - a[2]) * (b[2] - a[2]));
    float at = 0.f; // along this segment
    while (out.size() <= kMaxDabsPerStroke) {
      const float u = len > 0.f ? at / len : 0.f;
      const float need = step(pressure_at(k - 1) * (1.f - u) + pressure_at(k) * u) - since;
      if (at + need > len || !(at + need > at)) { // the end, or a step float can no longer take
        since += len - at;
        break;
      }
      at += need;
      since = 0.f;
      const float t = at / len, p = pressure_at(k - 1) * (1.f - t) + pressure_at(k) * t;
      out.push_back({{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])}, p,
                     {b[0] - a[0], b[1] - a[1], b[2] - a[2]}});
    }
  }
  return out;
}

} // namespace meshpaint
