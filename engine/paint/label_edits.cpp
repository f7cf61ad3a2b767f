// Label edits that are no brush: fill (the connected region of one class
// around a point) and merge (one class into another). Both decide on the
// host from the label layer as read, over welded vertices so that a region
// crosses patch sides and corners, and write every stored copy of a texel.

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

} // namespace

void PaintSurface::write_labels(std::vector<Float4>& material, const std::vector<std::size_t>& texels, int id)
{
  if (texels.empty())
    return;
  const LevelLayout l = atlas_->layout(level_);
  const std::size_t tile_texels = std::size_t(l.tile) * std::size_t(l.tile);
  std::vector<int> patches;
  for (const std::size_t t : texels)
    patches.push_back(int(t / tile_texels));
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  remember(patches);
  for (const std::size_t t : texels)
    material[t][2] = float(id);
  // A tile is one run of the patch-major layer: one write per patch.
  cl::CommandQueue& q = atlas_->runtime().queue();
  for (const int p : patches)
    q.enqueueWriteBuffer(device_->material, CL_FALSE, std::size_t(p) * tile_texels * sizeof(Float4),
                         tile_texels * sizeof(Float4), material.data() + std::size_t(p) * tile_texels);
  q.finish(); // before `material` goes
}

bool PaintSurface::fill_labels(const Vec3& point, float radius, const PaintSettings& settings)
{
  CullRecord seed{};
  if (!(radius > 0.f) || brush_patches(point, radius, nullptr, nullptr, 0.f, &seed).empty())
    return false;
  const LevelLayout l = atlas_->layout(level_);
  const std::size_t tile = std::size_t(l.tile), tile_texels = tile * tile;
  std::vector<Float4> material = read_layer(atlas_->runtime(), device_->material, l.texels());
  const std::size_t start = std::size_t(seed.patch) * tile_texels + std::size_t(seed.closest_texel);
  const float label = material[start][2];
  const int id = int(settings.value[CHANNEL_LABEL][0]);
  if (!label_open(settings, label) || label == float(id))
    return true;
  // The texels of each welded vertex (its stored copies), as lists.
  const std::vector<int>& vertex_of = texel_vertices();
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
    return true;
  std::vector<char> seen(vertices, 0);
  std::vector<int> queue{vertex_of[start]};
  seen[std::size_t(queue.front())] = 1;
  std::vector<std::size_t> region;
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
  write_labels(material, region, id);
  return true;
}

void PaintSurface::merge_labels(const PaintSettings& settings)
{
  const float from = float(settings.only_over_label);
  const int into = int(settings.value[CHANNEL_LABEL][0]);
  if (!label_open(settings, from) || from == float(into))
    return;
  std::vector<Float4> material = read_layer(atlas_->runtime(), device_->material, atlas_->layout(level_).texels());
  std::vector<std::size_t> texels;
  for (std::size_t t = 0; t < material.size(); ++t)
    if (material[t][2] == from)
      texels.push_back(t);
  write_labels(material, texels, into);
}

} // namespace meshpaint
