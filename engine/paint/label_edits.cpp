// Label edits that are no brush: fill and merge. Both decide on the host
// from the label layer as read, over welded vertices so that a region
// crosses patch sides and corners, and write every stored copy of a texel.

#include "paint/label_edits.h"

#include "paint/paint_device.h"

#include <algorithm> // for std::none_of, std::sort, std::unique
#include <utility>   // for std::pair

namespace meshpaint {
namespace {

//! Whether a stroke with these settings may overwrite class `label`.
bool label_open(const PaintSettings& p, float label)
{
  if (p.only_over_label >= 0 && label != float(p.only_over_label))
    return false;
  return std::none_of(p.locked_labels.begin(), p.locked_labels.end(), [&](int id) { return label == float(id); });
}

//! The label layer of `material` as read from the device.
std::vector<Float4> read_layer(Runtime& rt, const cl::Buffer& material, std::size_t texels)
{
  std::vector<Float4> m(texels);
  rt.queue().enqueueReadBuffer(material, CL_TRUE, 0, texels * sizeof(Float4), m.data());
  return m;
}

//! A texel's neighbours in its tile: the four along the sides first, then
//! the four across corners (a diagonal fill). Tiles share their border
//! texels (one welded vertex), so the diagonals of every tile about a patch
//! corner reach across that corner too.
constexpr std::pair<int, int> kNeighbours[8] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}};

//! The edit's tiles, from its texels.
void find_patches(const PaintState& state, LabelEdit& edit)
{
  const LevelLayout l = state.layout();
  const std::size_t tile_texels = std::size_t(l.tile) * std::size_t(l.tile);
  for (const std::size_t t : edit.texels)
    edit.patches.push_back(int(t / tile_texels));
  std::sort(edit.patches.begin(), edit.patches.end());
  edit.patches.erase(std::unique(edit.patches.begin(), edit.patches.end()), edit.patches.end());
}

} // namespace

void write_labels(const PaintState& state, LabelEdit& edit)
{
  if (edit.texels.empty())
    return;
  const LevelLayout l = state.layout();
  const std::size_t tile_texels = std::size_t(l.tile) * std::size_t(l.tile);
  std::vector<Float4>& material = edit.material;
  for (const std::size_t t : edit.texels)
    material[t][2] = float(edit.id);
  // A tile is one run of the patch-major layer: one write per patch.
  cl::CommandQueue& q = state.atlas.runtime().queue();
  for (const int p : edit.patches)
    q.enqueueWriteBuffer(state.device.material, CL_FALSE, std::size_t(p) * tile_texels * sizeof(Float4),
                         tile_texels * sizeof(Float4), material.data() + std::size_t(p) * tile_texels);
  q.finish(); // before `material` goes
}

LabelEdit fill_labels(const PaintState& state, const CullRecord& seed, const PaintSettings& settings)
{
  const LevelLayout l = state.layout();
  const std::size_t tile = std::size_t(l.tile), tile_texels = tile * tile;
  LabelEdit edit;
  edit.material = read_layer(state.atlas.runtime(), state.device.material, l.texels());
  const std::vector<Float4>& material = edit.material;
  const std::size_t start = std::size_t(seed.patch) * tile_texels + std::size_t(seed.closest_texel);
  const float label = material[start][2];
  const int id = int(settings.value[CHANNEL_LABEL][0]);
  edit.id = id;
  if (!label_open(settings, label) || label == float(id))
    return edit;
  // The texels of each welded vertex (its stored copies), as lists.
  const std::vector<int>& vertex_of = texel_vertices(state);
  std::size_t vertices = 0;
  for (const int v : vertex_of)
    vertices = std::max(vertices, std::size_t(v) + 1);
  std::vector<std::size_t> first(vertices + 1, 0), copies(vertex_of.size());
  for (const int v : vertex_of)
    ++first[std::size_t(v) + 1];
  for (std::size_t v = 0; v < vertices; ++v)
    first[v + 1] += first[v];
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (std::size_t t = 0; t < vertex_of.size(); ++t)
    copies[next[std::size_t(vertex_of[t])]++] = t;
  // Breadth first over vertices of the seed's class that the mask leaves
  // open (as a label dab at full strength would): the region's texels are
  // all copies of its vertices.
  const auto fillable = [&](std::size_t t) { return material[t][2] == label && material[t][3] <= 0.5f; };
  if (!fillable(start))
    return edit;
  std::vector<char> seen(vertices, 0);
  std::vector<int> queue{vertex_of[start]};
  seen[std::size_t(queue.front())] = 1;
  std::vector<std::size_t>& region = edit.texels;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t v = std::size_t(queue[head]);
    for (std::size_t c = first[v]; c < first[v + 1]; ++c) {
      const std::size_t t = copies[c];
      region.push_back(t);
      const std::size_t p = t / tile_texels, i = t % tile, j = t % tile_texels / tile;
      const std::size_t base = p * tile_texels;
      for (int k = 0; k < (settings.fill_diagonals ? 8 : 4); ++k) {
        const auto [di, dj] = kNeighbours[k];
        const long ni = long(i) + di, nj = long(j) + dj;
        if (ni < 0 || nj < 0 || ni >= long(tile) || nj >= long(tile))
          continue;
        const std::size_t u = base + std::size_t(nj) * tile + std::size_t(ni);
        const int w = vertex_of[u];
        if (!seen[std::size_t(w)] && fillable(u)) {
          seen[std::size_t(w)] = 1;
          queue.push_back(w);
        }
      }
    }
  }
  find_patches(state, edit);
  return edit;
}

LabelEdit merge_labels(const PaintState& state, const PaintSettings& settings)
{
  const float from = float(settings.only_over_label);
  LabelEdit edit;
  edit.id = int(settings.value[CHANNEL_LABEL][0]);
  if (!label_open(settings, from) || from == float(edit.id))
    return edit;
  edit.material = read_layer(state.atlas.runtime(), state.device.material, state.layout().texels());
  for (std::size_t t = 0; t < edit.material.size(); ++t)
    if (edit.material[t][2] == from)
      edit.texels.push_back(t);
  find_patches(state, edit);
  return edit;
}

} // namespace meshpaint
