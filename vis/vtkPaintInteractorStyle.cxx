#include "vtkPaintInteractorStyle.h"

#include "vtkPaintView.h" // for vtkPaintView

#include <vtkObjectFactory.h>          // for vtkStandardNewMacro
#include <vtkRenderWindowInteractor.h> // for vtkRenderWindowInteractor

vtkStandardNewMacro(vtkPaintInteractorStyle);

void vtkPaintInteractorStyle::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "View: " << this->View << "\n";
}

void vtkPaintInteractorStyle::OnLeftButtonDown()
{
  vtkRenderWindowInteractor* rwi = this->Interactor;
  const int* p = rwi->GetEventPosition();
  if (this->View && !rwi->GetAltKey() && !rwi->GetShiftKey() && !rwi->GetControlKey() &&
      this->View->BeginStroke(p[0], p[1]))
    return;
  this->Superclass::OnLeftButtonDown();
}

void vtkPaintInteractorStyle::OnLeftButtonUp()
{
  if (this->View && this->View->IsPainting()) {
    this->View->EndStroke();
    return;
  }
  this->Superclass::OnLeftButtonUp();
}

void vtkPaintInteractorStyle::OnMouseMove()
{
  const int* p = this->Interactor->GetEventPosition();
  if (this->View && this->View->IsPainting()) {
    this->View->ContinueStroke(p[0], p[1]);
    return;
  }
  this->Superclass::OnMouseMove();
  if (this->View && this->State == VTKIS_NONE)
    this->View->MoveCursor(p[0], p[1]);
}

void vtkPaintInteractorStyle::OnKeyPress()
{
  vtkRenderWindowInteractor* rwi = this->Interactor;
  if (this->View && rwi->GetKeySym())
    this->View->HandleKey(rwi->GetKeySym(), rwi->GetControlKey() != 0, rwi->GetShiftKey() != 0);
}

// VTK's character bindings (w, s, e, q, 3, ...) would fight the brush keys.
void vtkPaintInteractorStyle::OnChar() {}
