#include "vtkSurfacePicker.h"

#include <vtkActor.h>            // for vtkActor
#include <vtkCamera.h>           // for vtkCamera
#include <vtkCell.h>             // for vtkCell
#include <vtkCellType.h>         // for VTK_QUAD
#include <vtkDataArray.h>        // for vtkDataArray
#include <vtkDataObject.h>       // for vtkDataObject::FIELD_ASSOCIATION_CELLS
#include <vtkGenericCell.h>      // for vtkGenericCell
#include <vtkHardwareSelector.h> // for vtkHardwareSelector
#include <vtkMapper.h>           // for vtkMapper
#include <vtkMath.h>             // for vtkMath
#include <vtkObjectFactory.h>    // for vtkStandardNewMacro
#include <vtkOpenGLHardwareSelector.h> // for vtkOpenGLHardwareSelector
#include <vtkPointData.h>        // for vtkPointData
#include <vtkPolyData.h>         // for vtkPolyData
#include <vtkRenderWindow.h>     // for vtkRenderWindow
#include <vtkRenderer.h>         // for vtkRenderer
#include <vtkSmartPointer.h>     // for vtkSmartPointer
#include <vtkNew.h>              // for vtkNew

#include <algorithm> // for std::min, std::max, std::find_if
#include <vector>    // for std::vector

vtkStandardNewMacro(vtkSurfacePicker);

namespace {

// The item buffer with only the passes a pick reads: which actor, which
// cell. VTK's selector also renders composite-block and point-id passes,
// each a full frame of the surface; skipping them halves a capture.
class vtkCellItemSelector : public vtkOpenGLHardwareSelector
{
public:
  static vtkCellItemSelector* New();
  vtkTypeMacro(vtkCellItemSelector, vtkOpenGLHardwareSelector);

protected:
  bool PassRequired(int pass) override
  {
    if (pass == COMPOSITE_INDEX_PASS || pass == POINT_ID_LOW24 || pass == POINT_ID_HIGH24)
      return false;
    return this->Superclass::PassRequired(pass);
  }
};

vtkStandardNewMacro(vtkCellItemSelector);

} // namespace

struct vtkSurfacePicker::Internals
{
  vtkSmartPointer<vtkRenderer> renderer;
  std::vector<vtkSmartPointer<vtkActor>> actors;
  vtkNew<vtkCellItemSelector> selector;
  bool captured = false;
  // Each actor's surface as it was drawn into the buffers: cell ids refer
  // to it even if the actor shows another one since (a coarser level while
  // painting).
  std::vector<vtkSmartPointer<vtkPolyData>> drawn;
  int size[2] = {0, 0};
};

vtkSurfacePicker::vtkSurfacePicker() : Impl(new Internals)
{
  this->Impl->selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
}

vtkSurfacePicker::~vtkSurfacePicker() = default;

void vtkSurfacePicker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Captured: " << this->Impl->captured << "\n";
  os << indent << "Point: " << this->Point[0] << " " << this->Point[1] << " " << this->Point[2] << "\n";
  os << indent << "CellId: " << this->CellId << " (actor " << this->ActorIndex << ")\n";
  os << indent << "Facing: " << this->Facing << "\n";
  os << indent << "PatchResolution: " << this->PatchResolution << "\n";
  os << indent << "Patch: " << this->Patch << " (" << this->U << ", " << this->V << ")\n";
}

void vtkSurfacePicker::SetRenderer(vtkRenderer* renderer)
{
  this->Release();
  this->Impl->renderer = renderer;
  this->Modified();
}

vtkRenderer* vtkSurfacePicker::GetRenderer() { return this->Impl->renderer; }

void vtkSurfacePicker::SetActor(vtkActor* actor)
{
  this->RemoveAllActors();
  this->AddActor(actor);
}

void vtkSurfacePicker::AddActor(vtkActor* actor)
{
  this->Release();
  if (actor)
    this->Impl->actors.emplace_back(actor);
  this->Modified();
}

void vtkSurfacePicker::RemoveAllActors()
{
  this->Release();
  this->Impl->actors.clear();
  this->Modified();
}

int vtkSurfacePicker::GetNumberOfActors() { return int(this->Impl->actors.size()); }

vtkActor* vtkSurfacePicker::GetActor() { return this->GetActor(0); }

vtkActor* vtkSurfacePicker::GetActor(int k)
{
  return k >= 0 && k < this->GetNumberOfActors() ? this->Impl->actors[std::size_t(k)].GetPointer() : nullptr;
}

bool vtkSurfacePicker::IsCaptured() const { return this->Impl->captured; }

int vtkSurfacePicker::Capture()
{
  Internals& in = *this->Impl;
  this->Release();
  if (!in.renderer || !in.renderer->GetRenderWindow())
    return 0;
  const int* size = in.renderer->GetRenderWindow()->GetSize();
  if (size[0] <= 0 || size[1] <= 0)
    return 0;
  in.size[0] = size[0];
  in.size[1] = size[1];
  for (vtkActor* actor : in.actors)
    in.drawn.emplace_back(vtkPolyData::SafeDownCast(actor->GetMapper() ? actor->GetMapper()->GetInput() : nullptr));
  in.selector->SetRenderer(in.renderer);
  in.selector->SetArea(0, 0, unsigned(size[0] - 1), unsigned(size[1] - 1));
  in.captured = in.selector->CaptureBuffers();
  return in.captured ? 1 : 0;
}

void vtkSurfacePicker::Release()
{
  if (this->Impl->captured)
    this->Impl->selector->ClearBuffers();
  this->Impl->captured = false;
  this->Impl->drawn.clear();
}

int vtkSurfacePicker::Pick(int x, int y)
{
  Internals& in = *this->Impl;
  if (!in.captured && !this->Capture())
    return 0;
  if (x < 0 || y < 0 || x >= in.size[0] || y >= in.size[1])
    return 0;
  const unsigned int pixel[2] = {unsigned(x), unsigned(y)};
  unsigned int found[2];
  const vtkHardwareSelector::PixelInformation info = in.selector->GetPixelInformation(pixel, 0, found);
  if (!info.Valid || info.AttributeID < 0)
    return 0;
  const auto hit = std::find_if(in.actors.begin(), in.actors.end(),
                                [&](const vtkSmartPointer<vtkActor>& a) { return info.Prop == a.GetPointer(); });
  if (hit == in.actors.end())
    return 0;
  const std::size_t index = std::size_t(hit - in.actors.begin());
  vtkPolyData* poly = in.drawn[index];
  if (!poly || info.AttributeID >= poly->GetNumberOfCells())
    return 0;

  // The ray through the pixel centre, from the near to the far plane.
  double ends[2][4];
  for (int k = 0; k < 2; ++k) {
    in.renderer->SetDisplayPoint(x + 0.5, y + 0.5, double(k));
    in.renderer->DisplayToWorld();
    in.renderer->GetWorldPoint(ends[k]);
    for (int c = 0; c < 3; ++c)
      ends[k][c] /= ends[k][3];
  }
  vtkNew<vtkGenericCell> cell;
  poly->GetCell(info.AttributeID, cell);
  double t = 0, x_hit[3], pcoords[3];
  int sub_id = 0;
  std::vector<double> weights(std::size_t(cell->GetNumberOfPoints()));
  if (!cell->IntersectWithLine(ends[0], ends[1], 1e-6, t, x_hit, pcoords, sub_id)) {
    // The item buffer knows the cell, but the ray may pass its edge by a
    // rounding step: take the point of the ray nearest the cell's centre.
    cell->GetParametricCenter(pcoords);
    double centre[3], d[3], w[3];
    int sub = 0;
    cell->EvaluateLocation(sub, pcoords, centre, weights.data());
    vtkMath::Subtract(ends[1], ends[0], d);
    vtkMath::Subtract(centre, ends[0], w);
    const double s = vtkMath::Dot(w, d) / vtkMath::Dot(d, d);
    for (int c = 0; c < 3; ++c)
      x_hit[c] = ends[0][c] + s * d[c];
  }
  for (int c = 0; c < 3; ++c)
    this->Point[c] = x_hit[c];

  // Parametric coordinates and weights of the hit in its cell.
  double closest[3], dist2 = 0;
  cell->EvaluatePosition(x_hit, closest, sub_id, pcoords, dist2, weights.data());
  for (int c = 0; c < 2; ++c)
    pcoords[c] = std::min(1.0, std::max(0.0, pcoords[c]));

  // Normal: the point normals interpolated at the hit, else the cell's own.
  double n[3] = {0, 0, 0};
  if (vtkDataArray* normals = poly->GetPointData()->GetNormals()) {
    for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k) {
      double nk[3];
      normals->GetTuple(cell->GetPointId(k), nk);
      for (int c = 0; c < 3; ++c)
        n[c] += weights[std::size_t(k)] * nk[c];
    }
  }
  if (vtkMath::Normalize(n) == 0.0) {
    double a[3], b[3], p0[3], p1[3], p2[3];
    cell->GetPoints()->GetPoint(0, p0);
    cell->GetPoints()->GetPoint(1, p1);
    cell->GetPoints()->GetPoint(2, p2);
    vtkMath::Subtract(p1, p0, a);
    vtkMath::Subtract(p2, p0, b);
    vtkMath::Cross(a, b, n);
    vtkMath::Normalize(n);
  }
  for (int c = 0; c < 3; ++c)
    this->Normal[c] = n[c];
  double to_eye[3];
  vtkMath::Subtract(ends[0], ends[1], to_eye);
  vtkMath::Normalize(to_eye);
  this->Facing = vtkMath::Dot(n, to_eye);
  this->CellId = info.AttributeID;
  this->ActorIndex = int(index);
  // Quads of a welded level come n x n per patch, row by row, corner 0 at
  // texel (i, j) and the quad's r, s along the patch's i, j.
  const vtkIdType res = this->PatchResolution;
  if (res > 0 && cell->GetCellType() == VTK_QUAD) {
    const vtkIdType in_patch = this->CellId % (res * res);
    this->Patch = this->CellId / (res * res);
    this->U = (double(in_patch % res) + pcoords[0]) / double(res);
    this->V = (double(in_patch / res) + pcoords[1]) / double(res);
  } else {
    this->Patch = -1;
    this->U = this->V = 0;
  }
  return 1;
}
