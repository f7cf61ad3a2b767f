// Several objects painted by the same strokes, each with its own atlas.
#pragma once

#include "paint/paint_surface.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

class PaintScene
{
public:
  //! Adds an object; `name` names its outputs.
  void add(std::unique_ptr<PaintSurface> surface, std::string name);
  std::size_t size() const { return objects_.size(); }
  PaintSurface& surface(std::size_t k) { return *objects_[k].surface; }
  const std::string& name(std::size_t k) const { return objects_[k].name; }

  //! Runs one stroke over the scene. Each dab goes to every object with
  //! surface within its radius, so object, tangent and screen brushes paint
  //! across objects in contact; a parameter-space dab goes to the nearest
  //! object only. The stroke ends where no object is under the brush.
  //! Strokes that cover everything (wash, dip) go to every object. Returns
  //! a report per object.
  std::vector<StrokeReport> apply(const Stroke& stroke);

  //! Undo and redo whole strokes on every object.
  bool undo();
  bool redo();

private:
  struct Object
  {
    std::unique_ptr<PaintSurface> surface;
    std::string name;
  };
  std::vector<Object> objects_;
};

} // namespace meshpaint
