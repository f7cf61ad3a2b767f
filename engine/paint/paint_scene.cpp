#include "paint/paint_scene.h"

#include "core/errors.h"

#include <algorithm> // for std::fill, std::any_of
#include <limits>    // for std::numeric_limits

namespace meshpaint {

void PaintScene::add(std::shared_ptr<PaintSurface> surface, const std::string& name)
{
  if (!objects_.empty() && surface->level() != objects_.front().surface->level())
    throw InputError("'" + name + "' is at level " + std::to_string(surface->level()) + ", the scene at " +
                     std::to_string(objects_.front().surface->level()) + ": a scene paints at one level");
  const std::string stem = name.empty() ? "object" : name;
  const auto taken = [this](const std::string& n) {
    return std::any_of(objects_.begin(), objects_.end(), [&](const Object& o) { return o.name == n; });
  };
  std::string unique = stem;
  for (int k = 2; taken(unique); ++k)
    unique = stem + "_" + std::to_string(k);
  objects_.push_back({std::move(surface), unique});
}

std::string PaintScene::folder(const std::string& dir, std::size_t k) const
{
  return objects_.size() == 1 ? dir : dir + "/" + objects_[k].name;
}

const std::vector<Stroke>& PaintScene::history() const
{
  static const std::vector<Stroke> none;
  return objects_.empty() ? none : objects_.front().surface->history();
}

std::vector<StrokeReport> PaintScene::apply(const Stroke& stroke)
{
  std::vector<StrokeReport> reports;
  if (stroke.tool == Tool::Wash || stroke.tool == Tool::Dip || objects_.size() < 2) {
    for (Object& o : objects_)
      reports.push_back(o.surface->apply(stroke));
    return reports;
  }
  // Which objects each dab reaches; the stroke ends at the first dab that
  // reaches none (a grab takes its region at the first dab only).
  const std::vector<DabSample> samples = stroke_samples(stroke);
  const std::size_t dabs = stroke.tool == Tool::Grab ? 1 : samples.size();
  std::vector<std::vector<char>> mask(objects_.size(), std::vector<char>(samples.size(), 0));
  bool left = false;
  for (std::size_t k = 0; k < dabs && !left; ++k) {
    const float radius = stroke.radius * samples[k].pressure;
    if (!(radius > 0.f))
      continue;
    std::vector<float> distance(objects_.size());
    std::size_t nearest = 0;
    for (std::size_t o = 0; o < objects_.size(); ++o) {
      distance[o] = objects_[o].surface->distance_to(samples[k].centre, radius);
      if (distance[o] < distance[nearest])
        nearest = o;
    }
    left = distance[nearest] == std::numeric_limits<float>::infinity();
    for (std::size_t o = 0; o < objects_.size() && !left; ++o)
      mask[o][k] = stroke.space == SPACE_PARAMETER ? o == nearest : distance[o] <= radius;
  }
  if (stroke.tool == Tool::Grab) // the rest of the path belongs to the objects it took
    for (auto& m : mask)
      std::fill(m.begin() + 1, m.end(), m[0]);
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    reports.push_back(objects_[o].surface->apply(stroke, mask[o]));
    reports.back().left_surface = left;
  }
  return reports;
}

bool PaintScene::undo()
{
  bool any = false;
  for (Object& o : objects_)
    any = o.surface->undo() || any;
  return any;
}

bool PaintScene::redo()
{
  bool any = false;
  for (Object& o : objects_)
    any = o.surface->redo() || any;
  return any;
}

} // namespace meshpaint
