#include "mesh/channel_arrays.h"

#include "core/errors.h"
#include "core/format.h" // for meshpaint::excerpt, meshpaint::format_number
#include "mesh/base_mesh.h" // for meshpaint::kMaxCoordinate
#include "mesh/polygon_soup.h"

#include <algorithm> // for std::find_if
#include <cmath>     // for std::isfinite, std::fabs, std::round

namespace meshpaint {

int channel_component_count(const std::string& name)
{
  if (name == "diffuse" || name == "specular")
    return 3;
  if (name == "roughness" || name == "displacement" || name == "label" || name == "mask")
    return 1;
  return 0;
}

const std::string& channel_name_list()
{
  static const std::string names = "diffuse, specular, roughness, displacement, label, mask";
  return names;
}

std::string channel_value_problem(const std::string& channel, float v)
{
  if (!std::isfinite(v))
    return "is not finite";
  if (channel == "displacement")
    return std::fabs(v) <= kMaxCoordinate ? "" : "is beyond 1e15 in magnitude";
  if (channel == "label")
    return v >= 0.f && v <= float(kMaxLabelId) && std::round(v) == v
             ? ""
             : "is not an integer from 0 to " + std::to_string(kMaxLabelId);
  return v >= 0.f && v <= 1.f ? "" : "is not from 0 to 1";
}

ArrayImport parse_array_import(const std::string& text)
{
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
    throw InputError("--import-array needs NAME:CHANNEL, not '" + excerpt(text) + "'");
  ArrayImport a{text.substr(0, colon), text.substr(colon + 1)};
  if (channel_component_count(a.channel) == 0)
    throw InputError("--import-array " + excerpt(text) + ": unknown channel '" + excerpt(a.channel) + "' (" +
                     channel_name_list() + ")");
  return a;
}

void join_component_arrays(std::vector<VertexArray>& arrays)
{
  std::vector<VertexArray> joined;
  for (const VertexArray& first : arrays) {
    if (first.components != 1 || first.name.size() < 3)
      continue;
    const std::string stem = first.name.substr(0, first.name.size() - 2);
    for (const char* suffixes : {"rgb", "xyz"}) {
      if (first.name != stem + "_" + suffixes[0])
        continue;
      std::vector<const VertexArray*> parts{&first};
      for (int c = 1; c < 3; ++c) {
        const auto it = std::find_if(arrays.begin(), arrays.end(), [&](const VertexArray& a) {
          return a.components == 1 && a.name == stem + "_" + suffixes[c];
        });
        if (it != arrays.end())
          parts.push_back(&*it);
      }
      if (parts.size() != 3)
        continue;
      VertexArray a;
      a.name = stem;
      a.components = 3;
      a.integer = parts[0]->integer && parts[1]->integer && parts[2]->integer;
      a.values.resize(first.values.size() * 3);
      for (std::size_t v = 0; v < first.values.size(); ++v)
        for (std::size_t c = 0; c < 3; ++c)
          a.values[v * 3 + c] = parts[c]->values[v];
      joined.push_back(std::move(a));
    }
  }
  for (VertexArray& a : joined)
    arrays.push_back(std::move(a));
}

void take_channel_arrays(PolygonSoup& soup, const std::vector<ArrayImport>& requested, const std::string& where)
{
  std::vector<std::pair<const VertexArray*, std::string>> chosen; // array, channel
  const auto named = [&](const std::string& name) {
    return std::find_if(soup.arrays.begin(), soup.arrays.end(), [&](const VertexArray& a) { return a.name == name; });
  };
  const auto taken = [&](const std::string& channel) {
    return std::any_of(chosen.begin(), chosen.end(), [&](const auto& c) { return c.second == channel; });
  };
  for (const ArrayImport& r : requested) {
    const int k = channel_component_count(r.channel);
    if (k == 0)
      throw InputError("--import-array: unknown channel '" + excerpt(r.channel) + "' (" + channel_name_list() + ")");
    if (taken(r.channel))
      throw InputError("--import-array names the " + r.channel + " channel twice");
    const auto it = named(r.array);
    if (it == soup.arrays.end()) {
      std::string names;
      for (const VertexArray& a : soup.arrays)
        names += (names.empty() ? "" : ", ") + excerpt(a.name);
      throw InputError(where + "has no vertex array '" + excerpt(r.array) + "' for --import-array (" +
                       (names.empty() ? std::string("it has none") : "it has " + names) + ")");
    }
    if (it->components != k)
      throw InputError(where + "array '" + excerpt(r.array) + "' has " + std::to_string(it->components) +
                       " component" + (it->components == 1 ? "" : "s") + "; the " + r.channel + " channel takes " +
                       std::to_string(k));
    chosen.emplace_back(&*it, r.channel);
  }
  for (const VertexArray& a : soup.arrays)
    if (a.name != "label" && channel_component_count(a.name) == a.components && !taken(a.name))
      chosen.emplace_back(&a, a.name);

  for (const auto& [array, channel] : chosen) {
    const int k = array->components;
    std::vector<float> values(array->values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      values[i] = float(array->values[i]);
      const std::string problem = channel_value_problem(channel, values[i]);
      if (!problem.empty())
        throw InputError(where + "array '" + excerpt(array->name) + "' (for the " + channel + " channel): vertex " +
                         std::to_string(i / std::size_t(k)) + " " + problem + " (" + format_number(array->values[i]) +
                         ")");
    }
    if (channel == "diffuse") {
      soup.colours.assign(values.size() / 3, Vec3{0, 0, 0});
      for (std::size_t v = 0; v < soup.colours.size(); ++v)
        soup.colours[v] = {values[v * 3], values[v * 3 + 1], values[v * 3 + 2]};
      soup.colour_array = array->name;
    } else if (channel == "label") {
      soup.labels.assign(values.begin(), values.end());
      soup.label_array = array->name;
    } else {
      soup.channels.push_back({array->name, channel, k, std::move(values)});
    }
  }
  soup.arrays.clear();
}

std::vector<ChannelArray> without_values(const std::vector<ChannelArray>& arrays)
{
  std::vector<ChannelArray> out;
  for (const ChannelArray& a : arrays)
    out.push_back({a.array, a.channel, a.components, {}});
  return out;
}

void append_vertex(std::vector<ChannelArray>& to, const std::vector<ChannelArray>& from, std::size_t v)
{
  for (std::size_t i = 0; i < from.size(); ++i) {
    const std::size_t k = std::size_t(from[i].components);
    for (std::size_t a = 0; a < k; ++a) {
      const float value = from[i].values[v * k + a]; // a copy: `to` may grow `from`
      to[i].values.push_back(value);
    }
  }
}

} // namespace meshpaint
