#include "ViewText.h"

#include <vtkRenderer.h>     // for vtkRenderer
#include <vtkTextProperty.h> // for vtkTextProperty

namespace meshpaint {

void ViewText::add_to(vtkRenderer* renderer, const std::string& help)
{
  status_->GetTextProperty()->SetFontSize(15);
  status_->GetTextProperty()->SetColor(0.95, 0.95, 0.95);
  status_->SetPosition(10, 10);
  renderer->AddActor2D(status_);
  help_->GetTextProperty()->SetFontSize(14);
  help_->GetTextProperty()->SetFontFamilyToCourier();
  help_->GetTextProperty()->SetColor(1.0, 1.0, 0.8);
  help_->GetTextProperty()->SetVerticalJustificationToTop();
  help_->SetInput(help.c_str());
  help_->VisibilityOff();
  renderer->AddActor2D(help_);
}

void ViewText::update(const std::string& status, int window_height)
{
  help_->SetPosition(10, window_height - 10);
  status_->SetInput(status.c_str());
}

std::string status_line(const std::string& brush, int level, int lod_level, std::size_t strokes,
                        const std::string& message)
{
  std::string text = brush + "\nlevel " + std::to_string(level) + " (level of detail " + std::to_string(lod_level) +
                     ")   strokes " + std::to_string(strokes) + "   h: help";
  if (!message.empty())
    text += "   | " + message;
  return text;
}

} // namespace meshpaint
