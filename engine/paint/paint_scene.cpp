#include "paint/paint_scene.h"

#include "core/errors.h"

#include <algorithm> // for std::any_of
#include <exception> // for std::exception_ptr
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

const std::vector<Stroke>& PaintScene::undone() const
{
  static const std::vector<Stroke> none;
  return objects_.empty() ? none : objects_.front().surface->undone();
}

std::vector<StrokeReport> PaintScene::apply(const Stroke& stroke)
{
  begin_stroke(stroke);
  try {
    paint_dabs(stroke_samples(stroke));
  } catch (...) {
    take_back_failed(); // every object has closed the stroke as a step
    throw;
  }
  return end_stroke(stroke);
}

namespace {

//! Whether each object paints the whole stroke on its own: one object, or a
//! stroke that covers everything.
bool alone(const Stroke& stroke, std::size_t objects)
{
  return covers_everything(stroke.tool) || objects < 2;
}

} // namespace

void PaintScene::begin_stroke(const Stroke& stroke)
{
  open_ = stroke;
  masks_.assign(objects_.size(), {});
  decided_ = 0;
  left_ = false;
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    try {
      objects_[o].surface->begin_stroke(stroke);
    } catch (...) {
      for (std::size_t k = 0; k < o; ++k) // those begun already end, as one (empty) step each
        objects_[k].surface->end_stroke(stroke);
      throw;
    }
  }
}

bool PaintScene::paint_dabs(const std::vector<DabSample>& samples)
{
  try {
    return paint_new_dabs(samples);
  } catch (...) {
    // The object that failed has closed its stroke; the others close theirs,
    // so that every object keeps one history.
    for (Object& o : objects_)
      if (o.surface->stroke_open())
        try {
          o.surface->end_stroke(open_);
        } catch (...) {
        }
    masks_.clear();
    throw;
  }
}

bool PaintScene::paint_new_dabs(const std::vector<DabSample>& samples)
{
  if (alone(open_, objects_.size())) {
    bool on = false;
    for (Object& o : objects_)
      on = o.surface->paint_dabs(samples) || on;
    return on;
  }
  // Which objects each new dab reaches; the stroke ends at the first dab that
  // reaches none (a grab takes its region at the first dab only).
  for (auto& m : masks_)
    m.resize(samples.size(), 0);
  const bool grab = open_.tool == Tool::Grab;
  for (std::size_t k = decided_; k < samples.size() && !left_; ++k) {
    if (grab && k > 0) { // the rest of the path belongs to the objects it took
      for (auto& m : masks_)
        m[k] = m[0];
      continue;
    }
    const float radius = open_.brush.radius * samples[k].pressure;
    if (!(radius > 0.f))
      continue;
    std::vector<float> distance(objects_.size());
    std::size_t nearest = 0;
    for (std::size_t o = 0; o < objects_.size(); ++o) {
      distance[o] = objects_[o].surface->distance_to(samples[k].centre, radius);
      if (distance[o] < distance[nearest])
        nearest = o;
    }
    left_ = distance[nearest] == std::numeric_limits<float>::infinity();
    for (std::size_t o = 0; o < objects_.size() && !left_; ++o)
      masks_[o][k] = open_.brush.space == SPACE_PARAMETER ? o == nearest : distance[o] <= radius;
  }
  decided_ = samples.size();
  for (std::size_t o = 0; o < objects_.size(); ++o)
    objects_[o].surface->paint_dabs(samples, &masks_[o]);
  return !left_;
}

std::vector<StrokeReport> PaintScene::end_stroke(const Stroke& stroke)
{
  std::vector<StrokeReport> reports;
  std::exception_ptr failed;
  for (Object& o : objects_) {
    if (!o.surface->stroke_open()) // closed by a failure already
      continue;
    try { // every object ends its stroke, so that all stay in step
      reports.push_back(o.surface->end_stroke(stroke));
      if (!alone(stroke, objects_.size()))
        reports.back().left_surface = left_;
    } catch (...) {
      if (!failed)
        failed = std::current_exception();
    }
  }
  masks_.clear();
  if (failed)
    std::rethrow_exception(failed);
  return reports;
}

bool PaintScene::undo()
{
  bool any = false;
  for (Object& o : objects_)
    any = o.surface->undo() || any;
  return any;
}

bool PaintScene::take_back()
{
  bool any = false;
  for (Object& o : objects_)
    any = o.surface->take_back() || any;
  return any;
}

void PaintScene::take_back_failed() noexcept
{
  try {
    take_back();
  } catch (...) { // a device that failed may fail the undo too: the first error says why
  }
}

bool PaintScene::redo()
{
  bool any = false;
  for (Object& o : objects_)
    any = o.surface->redo() || any;
  return any;
}

} // namespace meshpaint
