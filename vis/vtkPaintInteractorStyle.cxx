#include "vtkPaintInteractorStyle.h"

#include "PaintControls.h" // for meshpaint::PaintControls

#include <vtkCommand.h>                // for vtkCommand
#include <vtkObjectFactory.h>          // for vtkStandardNewMacro
#include <vtkRenderWindowInteractor.h> // for vtkRenderWindowInteractor

vtkStandardNewMacro(vtkPaintInteractorStyle);

vtkPaintInteractorStyle::vtkPaintInteractorStyle()
{
  // The trackball announces its interactions as events; the controls hear
  // them when the interaction starts and ends, before the final render.
  this->AddObserver(vtkCommand::StartInteractionEvent, this, &vtkPaintInteractorStyle::OnInteraction);
  this->AddObserver(vtkCommand::EndInteractionEvent, this, &vtkPaintInteractorStyle::OnInteraction);
}

void vtkPaintInteractorStyle::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controls: " << this->Controls << "\n";
}

void vtkPaintInteractorStyle::OnInteraction(vtkObject*, unsigned long event, void*)
{
  if (this->Controls)
    this->Controls->camera_moving(event == vtkCommand::StartInteractionEvent);
}

void vtkPaintInteractorStyle::OnLeftButtonDown()
{
  vtkRenderWindowInteractor* rwi = this->Interactor;
  const int* p = rwi->GetEventPosition();
  if (this->Controls && !rwi->GetAltKey() && !rwi->GetShiftKey() && !rwi->GetControlKey() &&
      this->Controls->begin_stroke(p[0], p[1]))
    return;
  this->Superclass::OnLeftButtonDown();
}

void vtkPaintInteractorStyle::OnLeftButtonUp()
{
  if (this->Controls && this->Controls->painting()) {
    this->Controls->end_stroke();
    return;
  }
  this->Superclass::OnLeftButtonUp();
}

void vtkPaintInteractorStyle::OnMouseMove()
{
  const int* p = this->Interactor->GetEventPosition();
  if (this->Controls && this->Controls->painting()) {
    this->Controls->continue_stroke(p[0], p[1]);
    return;
  }
  this->Superclass::OnMouseMove();
  if (this->Controls && this->State == VTKIS_NONE)
    this->Controls->hover(p[0], p[1]);
}

void vtkPaintInteractorStyle::OnKeyPress()
{
  vtkRenderWindowInteractor* rwi = this->Interactor;
  if (this->Controls && rwi->GetKeySym())
    this->Controls->key(rwi->GetKeySym(), rwi->GetControlKey() != 0, rwi->GetShiftKey() != 0);
}

// VTK's character bindings (w, s, e, q, 3, ...) would fight the brush keys.
void vtkPaintInteractorStyle::OnChar() {}
