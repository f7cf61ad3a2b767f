// A painting session on a scene: strokes drawn by hand (begin, extend, end)
// or applied whole, undo and redo, and the recording, a stroke script that
// `meshpaint paint` replays to the same bits. The window, Python and the
// command line paint through it; it knows nothing of how points are picked.
#pragma once

#include "paint/paint_scene.h"
#include "paint/stroke.h"

#include <cstdint>  // for std::uint64_t
#include <optional> // for std::optional
#include <vector>   // for std::vector

namespace meshpaint {

class StrokeSession
{
public:
  explicit StrokeSession(PaintScene& scene) : scene_(scene) {}
  StrokeSession(const StrokeSession&) = delete;
  StrokeSession& operator=(const StrokeSession&) = delete;

  PaintScene& scene() { return scene_; }

  //! Starts a stroke drawn by hand: `stroke` holds its settings and its path
  //! so far (at least one point). Its dabs are painted as the path grows;
  //! the first waits for the second point, which gives it its heading.
  //! \throw InputError when a stroke is being drawn, the scene is empty, or
  //! the stroke has no point.
  void begin(const Stroke& stroke);
  //! Adds a point to the path (with its pressure where the stroke has
  //! pressure) and paints the dabs it completes. False once the stroke has
  //! left the surface: it takes no more points. A stroke that moves the
  //! surface is checked as apply() checks one after every piece painted:
  //! with a result that is not finite or beyond kMaxCoordinate it ends,
  //! taken back where the scene records undo steps.
  //! \throw InputError ("refused: ...") for such a result; the stroke is
  //! then no longer being drawn.
  bool extend(const Vec3& point, float pressure = 1.f);
  //! Ends the stroke being drawn: its last dabs are painted, and the stroke
  //! becomes one undo step and one stroke of the recording, painted once.
  //! \throw InputError for a result refused as extend() refuses one.
  std::vector<StrokeReport> end();
  bool drawing() const { return drawing_.has_value(); }
  //! The stroke being drawn (its path so far). \pre drawing()
  const Stroke& current() const { return *drawing_; }

  //! Applies a whole stroke (a script's), recorded as drawn ones are. A
  //! stroke that moves the surface (moves_surface()) is refused when its
  //! result is not finite or beyond kMaxCoordinate (surface_result_problem()):
  //! taken back where the scene records undo steps.
  //! \throw InputError naming the problem.
  std::vector<StrokeReport> apply(const Stroke& stroke);
  //! Whole strokes off and back on; false when there is nothing to undo
  //! (redo). Not while a stroke is being drawn.
  bool undo();
  bool redo();
  //! The strokes applied and not undone, as a script at `level`.
  StrokeScript recording(int level) const;

private:
  //! Several objects under a geometry brush: which objects a dab reaches
  //! depends on where the earlier dabs moved them, so the pieces drawn are
  //! previews, taken back when the stroke ends and the whole path applied
  //! (what a replay does).
  bool previews(const Stroke& stroke) const;
  //! Applies a piece as a preview, counting it for end() to take back.
  void preview(const Stroke& piece);
  void paint_new_dabs();
  //! Every object's change_count().
  std::vector<std::uint64_t> change_counts() const;
  //! A drawn stroke that moves the surface, after its newest piece: ends it,
  //! takes it back and throws when that piece left a result that is not
  //! finite; otherwise remembers the counts for the next check.
  void check_drawn_result();

  PaintScene& scene_;
  std::optional<Stroke> drawing_;
  bool ended_ = false;
  bool previewing_ = false;
  int previews_ = 0; // pieces applied as previews, to take back at the end
  std::vector<std::uint64_t> checked_; // a drawn stroke moving the surface: change counts at the last check
};

} // namespace meshpaint
