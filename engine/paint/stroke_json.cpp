#include "paint/stroke.h"

#include <nlohmann/json.hpp> // for nlohmann::json

namespace meshpaint {
namespace {

using nlohmann::json;

const char* const kChannelNames[CHANNEL_COUNT] = {"diffuse", "specular", "roughness", "displacement", "label", "mask"};

json point_list(const std::vector<Vec3>& points)
{
  json out = json::array();
  for (const Vec3& p : points)
    out.push_back({p[0], p[1], p[2]});
  return out;
}

//! The painted channels as the parser reads them back: colours with their
//! coverage, scalars as one number, labels as integers.
void write_channels(const Stroke& s, json& j)
{
  json channels = json::object(), alphas = json::object();
  for (int c = 0; c < CHANNEL_COUNT; ++c) {
    const Float4& v = s.value[std::size_t(c)];
    if (s.alpha[std::size_t(c)] == 0.f && v[0] == 0.f && v[1] == 0.f && v[2] == 0.f && v[3] == 0.f)
      continue;
    if (c == CHANNEL_DIFFUSE || c == CHANNEL_SPECULAR)
      channels[kChannelNames[c]] = {v[0], v[1], v[2], v[3]};
    else if (c == CHANNEL_LABEL)
      channels[kChannelNames[c]] = static_cast<long long>(v[0]);
    else
      channels[kChannelNames[c]] = v[0];
    alphas[kChannelNames[c]] = s.alpha[std::size_t(c)];
  }
  j["channels"] = channels;
  j["alphas"] = alphas;
}

json pattern_object(const Stroke& s)
{
  static const char* const types[] = {"", "noise", "turbulence", "marble", "bath", "image", "volume"};
  static const char* const coords[] = {"position", "uv", "screen"};
  json p = {{"type", types[s.pattern]},
            {"coord", coords[s.pattern_coord]},
            {"matte", s.matte == MATTE_OPAQUE ? "opaque" : "self"},
            {"octaves", s.octaves}};
  json rows = json::array();
  for (int r = 0; r < 3; ++r)
    rows.push_back({s.pattern_transform[std::size_t(4 * r)], s.pattern_transform[std::size_t(4 * r + 1)],
                    s.pattern_transform[std::size_t(4 * r + 2)], s.pattern_transform[std::size_t(4 * r + 3)]});
  p["transform"] = rows;
  if (!s.pattern_file.empty())
    p["file"] = s.pattern_file;
  return p;
}

json stroke_object(const Stroke& s)
{
  static const char* const falloffs[] = {"constant", "linear", "smoothstep", "gaussian"};
  static const char* const ops[] = {"copy", "over", "max", "add", "subtract"};
  json j = {{"tool", tool_name(s.tool)}, {"strength", s.strength}};
  const bool paints = s.tool == Tool::Paint || s.tool == Tool::Label || s.tool == Tool::Wash || s.tool == Tool::Dip;
  const bool everywhere = s.tool == Tool::Wash || s.tool == Tool::Dip;
  if (!everywhere) {
    j["points"] = point_list(s.points);
    j["radius"] = s.radius;
    j["spacing"] = s.spacing;
    j["falloff"] = falloffs[s.falloff];
    if (!s.pressure.empty())
      j["pressure"] = s.pressure;
    if (s.mirror_axis >= 0)
      j["mirror"] = std::string(1, char('x' + s.mirror_axis));
  }
  if (s.edit_level > 0)
    j["edit_level"] = s.edit_level;
  static const char* const spaces[] = {"object", "tangent", "screen", "parameter"};
  if (s.space != SPACE_OBJECT)
    j["space"] = spaces[s.space];
  if (s.has_camera)
    j["camera"] = {{"position", {s.camera.position[0], s.camera.position[1], s.camera.position[2]}},
                   {"focal_point", {s.camera.focal_point[0], s.camera.focal_point[1], s.camera.focal_point[2]}},
                   {"view_up", {s.camera.view_up[0], s.camera.view_up[1], s.camera.view_up[2]}},
                   {"view_angle", s.camera.view_angle}};
  if (s.paint_backfaces)
    j["backfaces"] = "paint";
  if (s.side > 0)
    j["side"] = s.side == 1 ? "outside" : "inside";
  if (s.spray_drops > 0)
    j["spray"] = {{"drops", s.spray_drops}, {"size", s.spray_size}, {"seed", s.spray_seed}};
  if (paints) {
    j["op"] = ops[s.op];
    if (s.remover) {
      j["mode"] = "remover";
    } else if (s.specular_coefficient >= 0.f) {
      // Polish and sandpaper differ only in their defaults; both written out.
      j["mode"] = "polish";
      j["coefficient"] = s.specular_coefficient;
      j["channels"] = {{"roughness", s.value[CHANNEL_ROUGHNESS][0]}};
      j["alphas"] = {{"roughness", s.alpha[CHANNEL_ROUGHNESS]}};
    } else {
      write_channels(s, j);
    }
    if (s.pattern != PATTERN_NONE)
      j["pattern"] = pattern_object(s);
  }
  switch (s.tool) {
  case Tool::Sculpt:
  case Tool::Inflate:
  case Tool::Flatten: j["amount"] = s.amount; break;
  case Tool::Smooth:
  case Tool::Blur:
    j["iterations"] = s.iterations;
    j["method"] = s.taubin ? "taubin" : "laplacian";
    j["lambda"] = s.lambda;
    if (s.tool == Tool::Smooth)
      j["target"] = s.target_colour ? "color" : "position";
    if (s.taubin || s.target_colour)
      j["mu"] = s.mu;
    break;
  default: break;
  }
  if (!s.stamp_file.empty())
    j["stamp"] = s.stamp_file;
  return j;
}

} // namespace

std::string stroke_json(const Stroke& stroke) { return stroke_object(stroke).dump(); }

std::string stroke_script_json(const StrokeScript& script)
{
  json j;
  if (script.level > 0)
    j["level"] = script.level;
  j["strokes"] = json::array();
  for (const Stroke& s : script.strokes)
    j["strokes"].push_back(stroke_object(s));
  return j.dump(1);
}

} // namespace meshpaint
