#include "paint/stroke_session.h"

#include "core/errors.h"
#include "paint/finite_result.h"

namespace meshpaint {

bool StrokeSession::previews(const Stroke& stroke) const
{
  const ToolFamily family = tool_family(stroke);
  return scene_.size() > 1 && (family == ToolFamily::Move || family == ToolFamily::Smooth);
}

void StrokeSession::begin(const Stroke& stroke)
{
  if (drawing_)
    throw InputError("a stroke is being drawn already: end it before the next begins");
  if (scene_.empty())
    throw InputError("no surface to paint: load a mesh first");
  if (stroke.points.empty())
    throw InputError("a stroke drawn by hand starts at a point");
  if (!stroke.pressure.empty() && stroke.pressure.size() != stroke.points.size())
    throw InputError("a stroke's pressure needs one value per point");
  drawing_ = stroke;
  ended_ = false;
  previews_ = 0;
  previewing_ = previews(stroke);
  checked_.clear();
  if (!previewing_ && moves_surface(stroke))
    checked_ = change_counts();
  if (previewing_) {
    if (stroke.points.size() > 1) {
      try {
        preview(stroke);
      } catch (...) {
        drawing_.reset(); // what the preview painted stays a stroke of its own
        throw;
      }
    }
    return;
  }
  try {
    scene_.begin_stroke(stroke);
  } catch (...) {
    drawing_.reset();
    throw;
  }
  paint_new_dabs();
}

void StrokeSession::preview(const Stroke& piece)
{
  // A piece that fails halfway is still a step of the scene's history (as
  // every stroke is), which end() takes back with the others.
  const std::size_t before = scene_.history().size();
  const std::vector<std::uint64_t> counts = change_counts();
  try {
    scene_.apply(piece);
  } catch (...) {
    previews_ += int(scene_.history().size() - before);
    throw;
  }
  ++previews_;
  for (std::size_t o = 0; o < scene_.size(); ++o) {
    const std::string problem = surface_result_problem(scene_.surface(o), counts[o]);
    if (problem.empty())
      continue;
    // The whole stroke so far is taken back, as apply() takes back one.
    drawing_.reset();
    for (; previews_ > 0 && scene_.take_back(); --previews_) {
    }
    throw InputError("refused: " + problem);
  }
}

void StrokeSession::paint_new_dabs()
{
  // A path of one point has no final dab yet: its heading needs the second.
  if (drawing_->points.size() < 2)
    return;
  try {
    ended_ = !scene_.paint_dabs(stroke_samples(*drawing_));
  } catch (...) {
    // The scene has closed the stroke as one step, with the path as it was
    // begun: taken back, as a refused stroke is, so that the history holds
    // no step whose replay would paint what this one did not.
    drawing_.reset();
    scene_.take_back_failed();
    throw;
  }
  check_drawn_result();
}

std::vector<std::uint64_t> StrokeSession::change_counts() const
{
  std::vector<std::uint64_t> counts;
  for (std::size_t o = 0; o < scene_.size(); ++o)
    counts.push_back(scene_.surface(o).change_count());
  return counts;
}

void StrokeSession::check_drawn_result()
{
  if (checked_.empty())
    return;
  for (std::size_t o = 0; o < scene_.size(); ++o) {
    const std::string problem = surface_result_problem(scene_.surface(o), checked_[o]);
    if (problem.empty())
      continue;
    // Closed as one undo step, as a failure while painting is, and taken back.
    const Stroke stroke = std::move(*drawing_);
    drawing_.reset();
    checked_.clear();
    scene_.end_stroke(stroke);
    scene_.take_back();
    throw InputError("refused: " + problem);
  }
  checked_ = change_counts();
}

bool StrokeSession::extend(const Vec3& point, float pressure)
{
  if (!drawing_)
    throw InputError("no stroke is being drawn: begin one first");
  if (ended_)
    return false;
  Stroke& s = *drawing_;
  s.points.push_back(point);
  if (!s.pressure.empty())
    s.pressure.push_back(pressure);
  if (previewing_) {
    Stroke piece = s;
    piece.points.assign(s.points.end() - 2, s.points.end());
    if (!s.pressure.empty())
      piece.pressure.assign(s.pressure.end() - 2, s.pressure.end());
    preview(piece);
    return true;
  }
  paint_new_dabs();
  return !ended_;
}

std::vector<StrokeReport> StrokeSession::end()
{
  if (!drawing_)
    throw InputError("no stroke is being drawn: begin one first");
  const Stroke stroke = std::move(*drawing_);
  drawing_.reset();
  if (previewing_) {
    int undone = 0;
    while (undone < previews_ && scene_.undo())
      ++undone;
    if (undone < previews_) {
      // The undo budget forgot a preview already (one step larger than the
      // whole budget): the pieces stay strokes of their own, as recorded.
      for (; undone > 0; --undone)
        scene_.redo();
      throw ResourceError("the undo budget is too small for this stroke: kept as " + std::to_string(previews_) +
                          " strokes");
    }
    return apply(stroke);
  }
  // The last dabs: those of the path's last piece, and a one-point path's.
  scene_.paint_dabs(stroke_samples(stroke));
  if (!checked_.empty()) {
    drawing_ = stroke;
    check_drawn_result();
    drawing_.reset();
    checked_.clear();
  }
  return scene_.end_stroke(stroke);
}

std::vector<StrokeReport> StrokeSession::apply(const Stroke& stroke)
{
  if (scene_.empty())
    throw InputError("no surface to paint: load a mesh first");
  if (!moves_surface(stroke))
    return scene_.apply(stroke);
  std::vector<std::uint64_t> before;
  for (std::size_t o = 0; o < scene_.size(); ++o)
    before.push_back(scene_.surface(o).change_count());
  std::vector<StrokeReport> reports = scene_.apply(stroke);
  for (std::size_t o = 0; o < scene_.size(); ++o) {
    const std::string problem = surface_result_problem(scene_.surface(o), before[o]);
    if (problem.empty())
      continue;
    scene_.take_back();
    throw InputError("refused: " + problem);
  }
  return reports;
}

bool StrokeSession::undo()
{
  if (drawing_)
    throw InputError("a stroke is being drawn: end it first");
  return scene_.undo();
}

bool StrokeSession::redo()
{
  if (drawing_)
    throw InputError("a stroke is being drawn: end it first");
  return scene_.redo();
}

StrokeScript StrokeSession::recording(int level) const
{
  StrokeScript script;
  script.level = level;
  script.strokes = scene_.history();
  return script;
}

} // namespace meshpaint
