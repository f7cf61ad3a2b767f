// vtkCatmullClarkAtlasFilter in a VTK pipeline.

#include "vtkCatmullClarkAtlasFilter.h"

#include <vtkCellArray.h>  // for vtkCellArray
#include <vtkDataArray.h>  // for vtkDataArray
#include <vtkNew.h>        // for vtkNew
#include <vtkPointData.h>  // for vtkPointData
#include <vtkPoints.h>     // for vtkPoints
#include <vtkPolyData.h>   // for vtkPolyData

#include <gtest/gtest.h>

namespace {

vtkNew<vtkPolyData> cube()
{
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> pts;
  const double p[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& q : p)
    pts->InsertNextPoint(q);
  vtkNew<vtkCellArray> quads;
  const vtkIdType f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto& q : f)
    quads->InsertNextCell(4, q);
  poly->SetPoints(pts);
  poly->SetPolys(quads);
  return poly;
}

TEST(CatmullClarkAtlasFilter, SubdividesACube)
{
  vtkNew<vtkCatmullClarkAtlasFilter> filter;
  auto input = cube();
  filter->SetInputData(input);
  filter->SetLevel(2);
  filter->Update();
  EXPECT_STREQ(filter->GetLastError(), "");
  vtkPolyData* out = filter->GetOutput();
  EXPECT_EQ(out->GetNumberOfPoints(), 98);
  EXPECT_EQ(out->GetNumberOfPolys(), 96);
  EXPECT_EQ(out->GetPointData()->GetNormals(), nullptr);

  filter->LimitOn();
  filter->Update();
  ASSERT_NE(filter->GetOutput()->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(filter->GetOutput()->GetPointData()->GetNormals()->GetNumberOfTuples(), 98);
}

TEST(CatmullClarkAtlasFilter, ReportsBadInput)
{
  vtkNew<vtkCatmullClarkAtlasFilter> filter;
  vtkNew<vtkPolyData> empty;
  filter->SetInputData(empty);
  filter->GlobalWarningDisplayOff();
  filter->Update();
  EXPECT_NE(std::string(filter->GetLastError()).find("has no faces"), std::string::npos)
    << filter->GetLastError();
}

} // namespace
