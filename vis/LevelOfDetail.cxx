#include "LevelOfDetail.h"

#include <vtkCellArray.h>      // for vtkCellArray
#include <vtkIdTypeArray.h>    // for vtkIdTypeArray
#include <vtkPointData.h>      // for vtkPointData
#include <vtkPolyData.h>       // for vtkPolyData

#include <algorithm> // for std::max

namespace meshpaint {

vtkSmartPointer<vtkPolyData> coarser_quads(vtkPolyData* full, int n, int stride)
{
  auto coarse = vtkSmartPointer<vtkPolyData>::New();
  coarse->SetPoints(full->GetPoints());
  coarse->GetPointData()->ShallowCopy(full->GetPointData());
  const vtkIdType per_patch = vtkIdType(n) * n;
  const vtkIdType patches = full->GetNumberOfPolys() / per_patch;
  const int m = n / stride;
  vtkCellArray* polys = full->GetPolys();
  auto fine_corner = [&](vtkIdType p, int i, int j, int corner) {
    vtkIdType count;
    const vtkIdType* ids;
    polys->GetCellAtId(p * per_patch + vtkIdType(j) * n + i, count, ids);
    return ids[corner];
  };
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(patches * m * m + 1);
  connectivity->SetNumberOfValues(4 * patches * m * m);
  vtkIdType q = 0;
  for (vtkIdType p = 0; p < patches; ++p)
    for (int J = 0; J < m; ++J)
      for (int I = 0; I < m; ++I, ++q) {
        const int i0 = I * stride, j0 = J * stride, i1 = i0 + stride - 1, j1 = j0 + stride - 1;
        offsets->SetValue(q, 4 * q);
        connectivity->SetValue(4 * q + 0, fine_corner(p, i0, j0, 0));
        connectivity->SetValue(4 * q + 1, fine_corner(p, i1, j0, 1));
        connectivity->SetValue(4 * q + 2, fine_corner(p, i1, j1, 2));
        connectivity->SetValue(4 * q + 3, fine_corner(p, i0, j1, 3));
      }
  offsets->SetValue(q, 4 * q);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  coarse->SetPolys(cells);
  return coarse;
}

void FrameTiming::add_frame(double ms, int width, int height, double quads)
{
  if (width != timed_size_[0] || height != timed_size_[1]) {
    ms_per_quad_ = 0;
    timed_size_ = {width, height};
  }
  const double per_quad = ms / std::max(1.0, quads);
  if (ms_per_quad_ == 0 || per_quad < ms_per_quad_)
    ms_per_quad_ = per_quad;
}

int FrameTiming::automatic_level(int level, double frame_rate, double quads) const
{
  const double budget_ms = 500.0 / frame_rate;
  int coarse = std::max(1, level - 1);
  quads /= 4.0;
  for (; coarse > 1 && quads * ms_per_quad_ > budget_ms; --coarse)
    quads /= 4.0;
  return coarse;
}

} // namespace meshpaint
