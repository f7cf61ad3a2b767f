// The Gaussian reduction kernels (the paper's subsampling operator).

#include "atlas/atlas.h"
#include "atlas/weld.h"
#include "support/copies.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cmath>   // for std::fabs
#include <cstring> // for std::memcmp

namespace meshpaint {
namespace {

double max_difference(const std::vector<Float4>& a, const std::vector<Float4>& b)
{
  double worst = 0;
  for (std::size_t t = 0; t < a.size(); ++t)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, double(std::fabs(a[t][k] - b[t][k])));
  return worst;
}

// Subdivision keeps an affine net affine and the binomial filter reproduces
// affine data, so reducing level l+1 must give back level l everywhere:
// inside patches, on patch sides, on the boundary curves and at corners.
TEST(Reduction, InvertsSubdivisionOnAffineData)
{
  Atlas atlas(test::runtime(), test::flat_grid(4), 5, AtlasStorage::Buffer);
  atlas.subdivide(1, 5);
  std::vector<std::vector<Float4>> subdivided;
  for (int l = 1; l <= 5; ++l)
    subdivided.push_back(atlas.read_positions(l));
  atlas.reduce(5, 1);
  for (int l = 1; l < 5; ++l)
    EXPECT_LE(max_difference(atlas.read_positions(l), subdivided[l - 1]), 1e-5) << "level " << l;
}

class ReductionOnShapes : public testing::TestWithParam<std::string>
{
};

// Weights sum to one everywhere (interior, patch sides, extraordinary,
// boundary and sharp corners): a surface collapsed to one point stays there.
TEST_P(ReductionOnShapes, WeightsSumToOne)
{
  Atlas atlas(test::runtime(), test::shape(GetParam()), 4, AtlasStorage::Buffer);
  const Float4 c{0.25f, -3.5f, 7.0f, 0.f};
  atlas.write_positions(4, std::vector<Float4>(atlas.layout(4).texels(), c));
  atlas.reduce(4, 1);
  for (int l = 1; l < 4; ++l)
    EXPECT_LE(max_difference(atlas.read_positions(l), std::vector<Float4>(atlas.layout(l).texels(), c)), 1e-5)
      << "level " << l;
}

// Every stored copy of a patch-side or corner vertex stays identical, and the
// reduced surface stays close to the one subdivision made (a smoothing, not a
// different shape).
TEST_P(ReductionOnShapes, CopiesStayIdenticalAndShapeStaysClose)
{
  const BaseMesh mesh = test::shape(GetParam());
  Atlas atlas(test::runtime(), mesh, 4, AtlasStorage::Buffer);
  atlas.subdivide(1, 4);
  const auto before = atlas.read_positions(2);
  atlas.reduce(4, 2);
  const auto after = atlas.read_positions(2);
  EXPECT_EQ(test::differing_copies(atlas.topology(), atlas.layout(2), after), 0u);
  EXPECT_LE(max_difference(before, after), 0.1 * mesh.diagonal());
}

INSTANTIATE_TEST_SUITE_P(Shapes, ReductionOnShapes, testing::ValuesIn(test::shape_names()));

} // namespace
} // namespace meshpaint
