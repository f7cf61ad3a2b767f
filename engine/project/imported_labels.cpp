#include "project/imported_labels.h"

#include "project/refined_values.h"
#include "project/vertex_channels.h"

#include <algorithm> // for std::stable_sort
#include <array>  // for std::array
#include <cmath>  // for std::floor
#include <set>    // for std::set
#include <string> // for std::to_string

namespace meshpaint {
namespace {

//! The label ids near a vertex as OpenSubdiv's primvar interpolation
//! carries them: each id's 0/1 field refined by the same weights as
//! positions, for the (at most four) ids with the largest values.
struct LabelVote
{
  static constexpr int kKept = 4;
  int candidates = 0;
  std::array<int, kKept> ids{};
  std::array<float, kKept> weights{};

  void Clear(void* = nullptr) { candidates = 0; }
  void add(int id, float w)
  {
    int k = 0;
    while (k < candidates && ids[std::size_t(k)] != id)
      ++k;
    if (k < candidates) {
      weights[std::size_t(k)] += w;
      return;
    }
    if (candidates < kKept) {
      ids[std::size_t(candidates)] = id;
      weights[std::size_t(candidates)] = w;
      ++candidates;
      return;
    }
    // Full: the new id replaces the weakest, if it is stronger.
    int weakest = 0;
    for (int c = 1; c < kKept; ++c)
      if (weights[std::size_t(c)] < weights[std::size_t(weakest)])
        weakest = c;
    if (w > weights[std::size_t(weakest)]) {
      ids[std::size_t(weakest)] = id;
      weights[std::size_t(weakest)] = w;
    }
  }
  void AddWithWeight(const LabelVote& src, float w)
  {
    for (int c = 0; c < src.candidates; ++c)
      add(src.ids[std::size_t(c)], w * src.weights[std::size_t(c)]);
  }
  //! The id with the largest value; a tie goes to the smallest id.
  int leading() const
  {
    int id = -1;
    float lead = 0;
    for (int c = 0; c < candidates; ++c) {
      const float weight = weights[std::size_t(c)];
      if (id < 0 || weight > lead || (weight == lead && ids[std::size_t(c)] < id)) {
        lead = weight;
        id = ids[std::size_t(c)];
      }
    }
    return id;
  }
};

} // namespace

void apply_imported_labels(PaintSurface& surface)
{
  // The atlas's base mesh, reordered along with its labels.
  const BaseMesh& base = surface.atlas().base_mesh();
  if (base.labels.size() != base.vertex_count())
    return;
  std::vector<LabelVote> coarse(base.vertex_count());
  for (std::size_t v = 0; v < coarse.size(); ++v)
    coarse[v].add(base.labels[v], 1.0f);
  const std::vector<LabelVote> fine = refined_to_painting_level(surface, std::move(coarse));
  std::vector<float> values(fine.size());
  for (std::size_t v = 0; v < fine.size(); ++v)
    values[v] = float(fine[v].leading());
  set_vertex_channel(surface, "label", values);
}

std::vector<LabelClass> imported_label_classes(const BaseMesh& mesh)
{
  std::vector<LabelClass> classes;
  std::set<int> named;
  for (const FileLabelClass& f : mesh.label_classes) {
    classes.push_back({f.id, f.name, f.colour});
    named.insert(f.id);
  }
  for (const int id : std::set<int>(mesh.labels.begin(), mesh.labels.end())) {
    if (id == 0 || named.count(id)) // unlabelled surface, or a class the file names
      continue;
    LabelClass c;
    c.id = id;
    c.name = "label " + std::to_string(id);
    // Hues a golden-ratio turn apart, so that neighbouring ids differ.
    const double hue = 6.0 * (double(id) * 0.6180339887 - std::floor(double(id) * 0.6180339887));
    const int sector = int(hue) % 6;
    const float f = float(hue - std::floor(hue));
    const float v = 0.9f, p = v * 0.35f, q = v * (1 - 0.65f * f), t = v * (1 - 0.65f * (1 - f));
    const std::array<Vec3, 6> rgb = {Vec3{v, t, p}, Vec3{q, v, p}, Vec3{p, v, t}, Vec3{p, q, v}, Vec3{t, p, v},
                                     Vec3{v, p, q}};
    c.colour = rgb[std::size_t(sector)];
    classes.push_back(c);
  }
  std::stable_sort(classes.begin(), classes.end(), [](const LabelClass& a, const LabelClass& b) { return a.id < b.id; });
  return classes;
}

} // namespace meshpaint
