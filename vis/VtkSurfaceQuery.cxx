#include "VtkSurfaceQuery.h"

#include <vtkCellArray.h>         // for vtkCellArray
#include <vtkGenericCell.h>       // for vtkGenericCell
#include <vtkPoints.h>            // for vtkPoints
#include <vtkPolyData.h>          // for vtkPolyData
#include <vtkSmartPointer.h>      // for vtkSmartPointer
#include <vtkStaticCellLocator.h> // for vtkStaticCellLocator

namespace meshpaint {
namespace {

class LocatorQuery : public SurfaceQuery
{
public:
  LocatorQuery(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles)
  {
    auto pts = vtkSmartPointer<vtkPoints>::New();
    pts->SetDataTypeToFloat();
    pts->SetNumberOfPoints(vtkIdType(points.size()));
    for (std::size_t v = 0; v < points.size(); ++v)
      pts->SetPoint(vtkIdType(v), points[v].data());
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->AllocateExact(vtkIdType(triangles.size()), vtkIdType(3 * triangles.size()));
    for (const auto& t : triangles) {
      const vtkIdType ids[3] = {t[0], t[1], t[2]};
      cells->InsertNextCell(3, ids);
    }
    surface_->SetPoints(pts);
    surface_->SetPolys(cells);
    locator_->SetDataSet(surface_);
    locator_->BuildLocator();
  }

  Vec3 closest_point(const Vec3& p) const override
  {
    const double x[3] = {p[0], p[1], p[2]};
    double closest[3], dist2 = 0;
    vtkIdType cell_id = -1;
    int sub = 0;
    locator_->FindClosestPoint(x, closest, cell_, cell_id, sub, dist2);
    return {float(closest[0]), float(closest[1]), float(closest[2])};
  }

  bool first_hit(const Vec3& a, const Vec3& b, Vec3& hit) const override
  {
    double p1[3] = {a[0], a[1], a[2]}, p2[3] = {b[0], b[1], b[2]}, x[3], pcoords[3], t = 0;
    int sub = 0;
    vtkIdType cell_id = -1;
    if (!locator_->IntersectWithLine(p1, p2, 0.0, t, x, pcoords, sub, cell_id, cell_))
      return false;
    hit = {float(x[0]), float(x[1]), float(x[2])};
    return true;
  }

private:
  vtkSmartPointer<vtkPolyData> surface_ = vtkSmartPointer<vtkPolyData>::New();
  vtkSmartPointer<vtkStaticCellLocator> locator_ = vtkSmartPointer<vtkStaticCellLocator>::New();
  vtkSmartPointer<vtkGenericCell> cell_ = vtkSmartPointer<vtkGenericCell>::New();
};

} // namespace

SurfaceQueryFactory vtk_surface_queries()
{
  return [](const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles) {
    return std::unique_ptr<SurfaceQuery>(new LocatorQuery(points, triangles));
  };
}

} // namespace meshpaint
