#include "project/vertex_channels.h"

#include "atlas/weld.h"
#include "core/errors.h"
#include "core/format.h" // for meshpaint::format_number
#include "project/content_checks.h" // for meshpaint::channel_value_problem

#include <algorithm> // for std::max_element
#include <cmath>     // for std::round

namespace meshpaint {
namespace {

//! The layer holding a channel and the first component it uses there.
std::pair<std::vector<Float4>*, int> place(PaintChannels& c, const std::string& name)
{
  if (name == "diffuse")
    return {&c.diffuse, 0};
  if (name == "specular")
    return {&c.specular, 0};
  if (name == "roughness")
    return {&c.material, 0};
  if (name == "displacement")
    return {&c.material, 1};
  if (name == "label")
    return {&c.material, 2};
  if (name == "mask")
    return {&c.material, 3};
  throw InputError("unknown channel '" + name + "' (" + channel_name_list() + ")");
}

} // namespace

int channel_components(const std::string& name)
{
  PaintChannels none;
  place(none, name);
  return channel_component_count(name);
}

std::vector<float> vertex_channel(PaintSurface& surface, const std::string& name)
{
  const int k = channel_components(name);
  PaintChannels c = surface.read_channels();
  const auto [layer, first] = place(c, name);
  const std::vector<int> map = weld_map(surface.atlas().topology(), surface.atlas().layout(surface.level()));
  const std::size_t vertices = std::size_t(*std::max_element(map.begin(), map.end())) + 1;
  std::vector<float> values(vertices * std::size_t(k));
  for (std::size_t t = 0; t < map.size(); ++t)
    for (int a = 0; a < k; ++a)
      values[std::size_t(map[t]) * std::size_t(k) + std::size_t(a)] = (*layer)[t][std::size_t(first + a)];
  return values;
}

void set_vertex_channel(PaintSurface& surface, const std::string& name, const std::vector<float>& values)
{
  const int k = channel_components(name);
  PaintChannels c = surface.read_channels();
  const auto [layer, first] = place(c, name);
  const std::vector<int> map = weld_map(surface.atlas().topology(), surface.atlas().layout(surface.level()));
  const std::size_t vertices = std::size_t(*std::max_element(map.begin(), map.end())) + 1;
  if (values.size() != vertices * std::size_t(k))
    throw InputError("channel '" + name + "' needs " + std::to_string(vertices) + " values of " +
                     std::to_string(k) + " component" + (k > 1 ? "s" : "") + ", not " +
                     std::to_string(values.size()) + " numbers");
  for (std::size_t t = 0; t < map.size(); ++t)
    for (int a = 0; a < k; ++a) {
      const float given = values[std::size_t(map[t]) * std::size_t(k) + std::size_t(a)];
      const float v = name == "label" ? std::round(given) : given;
      const std::string problem = channel_value_problem(name, v);
      if (!problem.empty())
        throw InputError("channel '" + name + "': the value of vertex " + std::to_string(map[t]) + " " + problem +
                         " (" + format_number(given) + ")");
      (*layer)[t][std::size_t(first + a)] = v;
    }
  surface.write_channels(c);
}

} // namespace meshpaint
