#include "PatchBorders.h"

#include <vtkCellArray.h>   // for vtkCellArray
#include <vtkIdTypeArray.h> // for vtkIdTypeArray
#include <vtkPolyData.h>    // for vtkPolyData

namespace meshpaint {

vtkSmartPointer<vtkPolyData> patch_borders(vtkPolyData* full, int n)
{
  auto lines = vtkSmartPointer<vtkPolyData>::New();
  lines->SetPoints(full->GetPoints());
  const vtkIdType per_patch = vtkIdType(n) * n;
  const vtkIdType patches = n > 0 ? full->GetNumberOfPolys() / per_patch : 0;
  vtkCellArray* polys = full->GetPolys();
  auto corner = [&](vtkIdType p, int i, int j, int c) {
    vtkIdType count;
    const vtkIdType* ids;
    polys->GetCellAtId(p * per_patch + vtkIdType(j) * n + i, count, ids);
    return ids[c];
  };
  const vtkIdType loop = 4 * vtkIdType(n) + 1; // around the patch, back to the first corner
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(patches + 1);
  connectivity->SetNumberOfValues(patches * loop);
  vtkIdType k = 0;
  for (vtkIdType p = 0; p < patches; ++p) {
    offsets->SetValue(p, p * loop);
    for (int i = 0; i < n; ++i) // the first row's outer edges
      connectivity->SetValue(k++, corner(p, i, 0, 0));
    for (int j = 0; j < n; ++j) // the last column's
      connectivity->SetValue(k++, corner(p, n - 1, j, 1));
    for (int i = n - 1; i >= 0; --i) // the last row's, backwards
      connectivity->SetValue(k++, corner(p, i, n - 1, 2));
    for (int j = n - 1; j >= 0; --j) // the first column's, backwards
      connectivity->SetValue(k++, corner(p, 0, j, 3));
    connectivity->SetValue(k++, corner(p, 0, 0, 0));
  }
  offsets->SetValue(patches, patches * loop);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  lines->SetLines(cells);
  return lines;
}

} // namespace meshpaint
