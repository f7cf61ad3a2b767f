// The legend beside the painting view: a colour bar for a channel shown
// through a colour map, the label classes with their names and colours for
// the label channel, nothing for the materials.
#ifndef ChannelLegend_h
#define ChannelLegend_h

#include "ChannelDisplay.h" // for meshpaint::ShownChannel, LabelClass

#include <vtkNew.h>            // for vtkNew
#include <vtkScalarBarActor.h> // for vtkScalarBarActor

#include <vector> // for std::vector

class vtkPolyData;
class vtkRenderer;

namespace meshpaint {

class ChannelLegend
{
public:
  //! Adds the (hidden) bar to `renderer`.
  void add_to(vtkRenderer* renderer);
  //! Shows the legend of `channel` on `surface` (to_polydata() arrays), or hides it.
  void update(ShownChannel channel, vtkPolyData* surface, const std::vector<LabelClass>& labels);
  bool visible() const { return bar_->GetVisibility() != 0; }

private:
  vtkNew<vtkScalarBarActor> bar_;
};

} // namespace meshpaint

#endif
