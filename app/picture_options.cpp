#include "picture_options.h"

#include "core/errors.h"

#include <cmath>   // for std::isfinite
#include <sstream> // for std::istringstream

namespace meshpaint::cli {
namespace {

//! Numbers separated by `separator`, exactly `count` of them, or nothing.
std::vector<double> numbers(const std::string& text, char separator, std::size_t count)
{
  std::vector<double> out;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(part, &used);
    } catch (const std::exception&) {
      return {};
    }
    if (used != part.size() || !std::isfinite(v))
      return {};
    out.push_back(v);
  }
  return out.size() == count ? out : std::vector<double>{};
}

} // namespace

PictureOptions picture_options(const Args& args)
{
  PictureOptions o;
  if (args.has("--camera")) {
    const std::vector<double> v = numbers(args.value("--camera"), ',', 3);
    if (v.empty() || v[2] <= 0)
      throw InputError("--camera must be AZIMUTH,ELEVATION,ZOOM (degrees, degrees, zoom > 0), not '" +
                       args.value("--camera") + "'");
    o.camera = {v[0], v[1], v[2]};
  }
  if (args.has("--size")) {
    const std::vector<double> v = numbers(args.value("--size"), 'x', 2);
    if (v.empty() || v[0] != int(v[0]) || v[1] != int(v[1]) || v[0] < 16 || v[1] < 16 || v[0] > 8192 ||
        v[1] > 8192)
      throw InputError("--size must be WIDTHxHEIGHT, 16 to 8192 pixels each, not '" + args.value("--size") + "'");
    o.width = int(v[0]);
    o.height = int(v[1]);
  }
  return o;
}

} // namespace meshpaint::cli
