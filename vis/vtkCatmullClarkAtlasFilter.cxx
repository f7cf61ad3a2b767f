#include "vtkCatmullClarkAtlasFilter.h"

#include "SurfaceConversion.h" // for meshpaint::to_base_mesh, to_polydata

#include "atlas/atlas.h" // for meshpaint::Atlas
#include "atlas/weld.h"  // for meshpaint::level_surface

#include <vtkInformation.h>       // for vtkInformation
#include <vtkInformationVector.h> // for vtkInformationVector
#include <vtkObjectFactory.h>     // for vtkStandardNewMacro
#include <vtkPolyData.h>          // for vtkPolyData

vtkStandardNewMacro(vtkCatmullClarkAtlasFilter);

vtkCatmullClarkAtlasFilter::vtkCatmullClarkAtlasFilter() = default;
vtkCatmullClarkAtlasFilter::~vtkCatmullClarkAtlasFilter() = default;

void vtkCatmullClarkAtlasFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "Limit: " << (this->Limit ? "On" : "Off") << "\n";
  os << indent << "Device: " << (this->Device.empty() ? "(default)" : this->Device) << "\n";
}

int vtkCatmullClarkAtlasFilter::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                            vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->LastError.clear();
  try {
    using namespace meshpaint;
    const BaseMesh mesh = to_base_mesh(input, "input");
    auto runtime = Runtime::open(this->Device);
    Atlas atlas(runtime, mesh, this->Level, default_storage(runtime->info()));
    atlas.subdivide(1, this->Level);
    output->ShallowCopy(to_polydata(level_surface(atlas, this->Level, this->Limit)));
  } catch (const cl::Error& e) {
    this->LastError = meshpaint::describe(e);
  } catch (const std::exception& e) {
    this->LastError = e.what();
  }
  if (!this->LastError.empty()) {
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  return 1;
}
