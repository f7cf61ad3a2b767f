#include "mesh/polygon_soup.h"

#include <algorithm> // for std::min, std::max
#include <cmath>     // for std::sqrt

#include "core/errors.h"

namespace meshpaint {

const std::vector<std::string>& label_array_names()
{
  static const std::vector<std::string> names = {"label", "labels", "class", "segment"};
  return names;
}

void check_label_ids(const std::vector<int>& labels, const std::string& where)
{
  constexpr int kLargest = kMaxLabelId;
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (labels[v] < 0 || labels[v] > kLargest)
      throw InputError(where + "vertex " + std::to_string(v) + " has label " + std::to_string(labels[v]) +
                       ", outside 0 to " + std::to_string(kLargest));
}

void colours_from_faces(PolygonSoup& soup)
{
  if (soup.face_colours.empty() || !soup.colours.empty())
    return;
  std::vector<Vec3> sum(soup.points.size(), Vec3{0, 0, 0});
  std::vector<int> count(soup.points.size(), 0);
  for (std::size_t f = 0; f < soup.faces.size(); ++f)
    for (const int v : soup.faces[f]) {
      for (int a = 0; a < 3; ++a)
        sum[std::size_t(v)][a] += soup.face_colours[f][a];
      ++count[std::size_t(v)];
    }
  soup.colours.resize(soup.points.size(), Vec3{0.5f, 0.5f, 0.5f});
  for (std::size_t v = 0; v < sum.size(); ++v)
    if (count[v] > 0)
      for (int a = 0; a < 3; ++a)
        soup.colours[v][a] = sum[v][a] / float(count[v]);
}

double diagonal_of(const std::vector<Vec3>& points)
{
  Vec3 lo = points.front(), hi = lo;
  for (const Vec3& p : points)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  double d2 = 0;
  for (int a = 0; a < 3; ++a)
    d2 += double(hi[a] - lo[a]) * double(hi[a] - lo[a]);
  return std::sqrt(d2);
}

} // namespace meshpaint
