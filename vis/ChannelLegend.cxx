#include "ChannelLegend.h"

#include <vtkLookupTable.h>   // for vtkLookupTable
#include <vtkRenderer.h>      // for vtkRenderer
#include <vtkScalarsToColors.h> // for vtkScalarsToColors
#include <vtkTextProperty.h>  // for vtkTextProperty
#include <vtkVariant.h>       // for vtkVariant

namespace meshpaint {

void ChannelLegend::add_to(vtkRenderer* renderer)
{
  bar_->SetPosition(0.9, 0.25);
  bar_->SetWidth(0.07);
  bar_->SetHeight(0.5);
  bar_->SetMaximumWidthInPixels(60);
  bar_->SetNumberOfLabels(5);
  bar_->GetLabelTextProperty()->SetFontSize(12);
  bar_->GetTitleTextProperty()->SetFontSize(14);
  bar_->PickableOff(); // the item buffer must see the surface through it
  bar_->VisibilityOff();
  renderer->AddViewProp(bar_);
}

void ChannelLegend::update(ShownChannel channel, vtkPolyData* surface, const std::vector<LabelClass>& labels)
{
  if (channel == ShownChannel::label && !labels.empty()) {
    // The classes as a categorical table: one swatch per class, with its name.
    vtkNew<vtkLookupTable> table;
    table->IndexedLookupOn();
    table->SetNumberOfTableValues(vtkIdType(labels.size()));
    for (std::size_t k = 0; k < labels.size(); ++k) {
      const LabelClass& c = labels[k];
      table->SetTableValue(vtkIdType(k), c.colour[0], c.colour[1], c.colour[2], 1.0);
      table->SetAnnotation(vtkVariant(c.id), c.name);
    }
    bar_->SetLookupTable(table);
    bar_->SetTitle("label");
    bar_->VisibilityOn();
    return;
  }
  vtkSmartPointer<vtkScalarsToColors> map = surface ? channel_colour_map(surface, channel) : nullptr;
  if (!map) {
    bar_->VisibilityOff();
    return;
  }
  bar_->SetLookupTable(map);
  bar_->SetTitle(shown_channel_name(channel).c_str());
  bar_->VisibilityOn();
}

} // namespace meshpaint
