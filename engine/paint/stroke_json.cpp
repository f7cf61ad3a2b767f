#include "paint/stroke.h"

#include "paint/stroke_schema.h"

#include <nlohmann/json.hpp> // for nlohmann::json

#include <variant> // for std::visit

namespace meshpaint {
namespace {

using nlohmann::json;

json point_list(const std::vector<Vec3>& points)
{
  json out = json::array();
  for (const Vec3& p : points)
    out.push_back({p[0], p[1], p[2]});
  return out;
}

//! The painted channels as the parser reads them back: colours with their
//! coverage, scalars as one number, labels as integers.
void write_channels(const PaintSettings& p, json& j)
{
  const std::vector<std::string>& names = channel_names();
  json channels = json::object(), alphas = json::object();
  for (int c = 0; c < CHANNEL_COUNT; ++c) {
    const Float4& v = p.value[std::size_t(c)];
    if (p.alpha[std::size_t(c)] == 0.f && v[0] == 0.f && v[1] == 0.f && v[2] == 0.f && v[3] == 0.f)
      continue;
    if (c == CHANNEL_DIFFUSE || c == CHANNEL_SPECULAR)
      channels[names[std::size_t(c)]] = {v[0], v[1], v[2], v[3]};
    else if (c == CHANNEL_LABEL)
      channels[names[std::size_t(c)]] = static_cast<long long>(v[0]);
    else
      channels[names[std::size_t(c)]] = v[0];
    alphas[names[std::size_t(c)]] = p.alpha[std::size_t(c)];
  }
  j["channels"] = channels;
  j["alphas"] = alphas;
}

json pattern_object(const Pattern& pattern)
{
  json p = {{"type", name_of(pattern_key("type"), pattern.kind)},
            {"coord", name_of(pattern_key("coord"), pattern.coord)},
            {"matte", name_of(pattern_key("matte"), pattern.matte)},
            {"octaves", pattern.octaves}};
  json rows = json::array();
  for (int r = 0; r < 3; ++r)
    rows.push_back({pattern.transform[std::size_t(4 * r)], pattern.transform[std::size_t(4 * r + 1)],
                    pattern.transform[std::size_t(4 * r + 2)], pattern.transform[std::size_t(4 * r + 3)]});
  p["transform"] = rows;
  if (!pattern.file.empty())
    p["file"] = pattern.file;
  return p;
}

void write_settings(const PaintSettings& p, Tool, json& j)
{
  if (p.spray_drops > 0)
    j["spray"] = {{"drops", p.spray_drops}, {"size", p.spray_size}, {"seed", p.spray_seed}};
  j["op"] = name_of(stroke_key("op"), p.op);
  if (p.remover) {
    j["mode"] = "remover";
  } else if (p.specular_coefficient >= 0.f) {
    // Polish and sandpaper differ only in their defaults; both written out.
    j["mode"] = "polish";
    j["coefficient"] = p.specular_coefficient;
    j["channels"] = {{"roughness", p.value[CHANNEL_ROUGHNESS][0]}};
    j["alphas"] = {{"roughness", p.alpha[CHANNEL_ROUGHNESS]}};
  } else {
    write_channels(p, j);
  }
  if (p.pattern.kind != PATTERN_NONE)
    j["pattern"] = pattern_object(p.pattern);
  if (!p.locked_labels.empty())
    j["locked_labels"] = p.locked_labels;
  if (p.only_over_label >= 0)
    j["only_over_label"] = p.only_over_label;
  if (p.fill_diagonals) // the default stays unwritten: recordings from before read the same
    j["connect"] = name_of(stroke_key("connect"), 1);
}

void write_settings(const SmoothSettings& m, Tool tool, json& j)
{
  j["iterations"] = m.iterations;
  j["method"] = name_of(stroke_key("method"), m.taubin ? 1 : 0);
  j["lambda"] = m.lambda;
  if (tool == Tool::Smooth)
    j["target"] = name_of(stroke_key("target"), m.target_colour ? 1 : 0);
  if (m.taubin || m.target_colour)
    j["mu"] = m.mu;
}

void write_settings(const MoveSettings& m, Tool tool, json& j)
{
  if (tool != Tool::Grab)
    j["amount"] = m.amount;
}

void write_settings(const SmearSettings&, Tool, json&) {}

json stroke_object(const Stroke& s)
{
  json j = {{"tool", tool_name(s.tool)}, {"strength", s.brush.strength}};
  const bool everywhere = covers_everything(s.tool);
  if (!everywhere) {
    j["points"] = point_list(s.points);
    j["radius"] = s.brush.radius;
    j["spacing"] = s.brush.spacing;
    j["falloff"] = name_of(stroke_key("falloff"), s.brush.falloff);
    if (!s.pressure.empty())
      j["pressure"] = s.pressure;
    if (s.brush.mirror_axis >= 0)
      j["mirror"] = name_of(stroke_key("mirror"), s.brush.mirror_axis);
  }
  if (s.edit_level() > 0)
    j["edit_level"] = s.edit_level();
  if (s.brush.space != SPACE_OBJECT)
    j["space"] = name_of(stroke_key("space"), s.brush.space);
  if (s.brush.has_camera)
    j["camera"] = {{"position", {s.brush.camera.position[0], s.brush.camera.position[1], s.brush.camera.position[2]}},
                   {"focal_point", {s.brush.camera.focal_point[0], s.brush.camera.focal_point[1], s.brush.camera.focal_point[2]}},
                   {"view_up", {s.brush.camera.view_up[0], s.brush.camera.view_up[1], s.brush.camera.view_up[2]}},
                   {"view_angle", s.brush.camera.view_angle}};
  if (s.brush.paint_backfaces)
    j["backfaces"] = name_of(stroke_key("backfaces"), 1);
  if (s.brush.side > 0)
    j["side"] = name_of(stroke_key("side"), s.brush.side);
  std::visit([&](const auto& settings) { write_settings(settings, s.tool, j); }, s.settings);
  if (!s.brush.stamp_file.empty())
    j["stamp"] = s.brush.stamp_file;
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
