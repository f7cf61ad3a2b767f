// The painting window's text: the status line at the bottom left (brush,
// level, strokes, the last message) and the help overlay at the top left.
#ifndef ViewText_h
#define ViewText_h

#include <vtkNew.h>       // for vtkNew
#include <vtkTextActor.h> // for vtkTextActor

#include <cstddef> // for std::size_t
#include <string>  // for std::string

class vtkRenderer;

namespace meshpaint {

class ViewText
{
public:
  //! Adds the status line and the help overlay (hidden) showing `help`.
  void add_to(vtkRenderer* renderer, const std::string& help);
  //! Shows `status` and keeps the help below the top of a window
  //! `window_height` pixels high.
  void update(const std::string& status, int window_height);
  void set_help_visible(bool visible) { help_->SetVisibility(visible); }
  bool help_visible() const { return help_->GetVisibility() != 0; }

private:
  vtkNew<vtkTextActor> status_;
  vtkNew<vtkTextActor> help_;
};

//! The status line: the brush (BrushSettings::describe()), the painting
//! level and the level drawn while moving, the strokes so far, and the last
//! message when there is one.
std::string status_line(const std::string& brush, int level, int lod_level, std::size_t strokes,
                        const std::string& message);

} // namespace meshpaint

#endif
