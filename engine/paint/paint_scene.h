// Several objects painted by the same strokes, each with its own atlas.
#pragma once

#include "paint/paint_surface.h"

#include <memory> // for std::shared_ptr
#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

class PaintScene
{
public:
  //! Adds an object; `name` names its outputs and is made unique in the
  //! scene ("name_2", "name_3", ...; empty: "object"). The surface may be
  //! shared with others (a window and a filter painting the same surface).
  //! \throw InputError when its level differs from the scene's.
  void add(std::shared_ptr<PaintSurface> surface, const std::string& name);
  //! Removes every object.
  void clear() { objects_.clear(); }
  std::size_t size() const { return objects_.size(); }
  bool empty() const { return objects_.empty(); }
  PaintSurface& surface(std::size_t k) { return *objects_[k].surface; }
  const std::shared_ptr<PaintSurface>& shared(std::size_t k) const { return objects_[k].surface; }
  const std::string& name(std::size_t k) const { return objects_[k].name; }
  //! Where object k's outputs go under `dir`: `dir` itself for a scene of
  //! one object, else `dir`/name.
  std::string folder(const std::string& dir, std::size_t k) const;

  //! Runs one stroke over the scene. Each dab goes to every object with
  //! surface within its radius, so object, tangent and screen brushes paint
  //! across objects in contact; a parameter-space dab goes to the nearest
  //! object only. The stroke ends where no object is under the brush.
  //! Strokes that cover everything (wash, dip) go to every object. Returns
  //! a report per object. A stroke that fails while painting is taken back
  //! (take_back_failed()) before the error goes on.
  std::vector<StrokeReport> apply(const Stroke& stroke);
  //! The same in three steps, for a stroke painted while it is drawn (as
  //! PaintSurface::begin_stroke(), paint_dabs(), end_stroke()). Each call of
  //! paint_dabs() decides for its new dabs which objects they reach before
  //! painting them, so a path applied whole gives apply()'s bits; a
  //! geometry stroke drawn in pieces over several objects may choose
  //! differently (the objects moved in between), which StrokeSession avoids.
  void begin_stroke(const Stroke& stroke);
  bool paint_dabs(const std::vector<DabSample>& samples);
  std::vector<StrokeReport> end_stroke(const Stroke& stroke);

  //! Undo and redo whole strokes on every object.
  bool undo();
  bool redo();
  //! PaintSurface::take_back() on every object.
  bool take_back();
  //! take_back() of a stroke that failed while painting, which every object
  //! has closed: a stroke that failed is neither in the history nor in its
  //! replay. Its own failure is ignored, so the first error is the one told.
  void take_back_failed() noexcept;
  //! The strokes applied so far: every object records every stroke, also
  //! one that did not reach it, so the first object's history is the
  //! scene's. Empty for an empty scene.
  const std::vector<Stroke>& history() const;
  //! The strokes undone and not yet redone (the first object's), the next to redo last.
  const std::vector<Stroke>& undone() const;

private:
  struct Object
  {
    std::shared_ptr<PaintSurface> surface;
    std::string name;
  };
  bool paint_new_dabs(const std::vector<DabSample>& samples);

  std::vector<Object> objects_;
  // The stroke being drawn over several objects: per object, which of its
  // dabs are the object's; the first dab that reaches none ends it.
  Stroke open_;
  std::vector<std::vector<char>> masks_;
  std::size_t decided_ = 0;
  bool left_ = false;
};

} // namespace meshpaint
