// The two atlas storage paths (linear buffers, image2d objects) run the same
// kernel source and must give the same bits for every operation.

#include "atlas/atlas.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cstring> // for std::memcmp

namespace meshpaint {
namespace {

std::size_t differing_texels(const std::vector<Float4>& a, const std::vector<Float4>& b)
{
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    n += std::memcmp(&a[i], &b[i], sizeof(Float4)) != 0;
  return n;
}

class StoragePaths : public testing::TestWithParam<std::string>
{
};

TEST_P(StoragePaths, BufferAndImageAgreeBitForBit)
{
  if (!test::runtime()->info().images)
    GTEST_SKIP() << test::runtime()->info().name << " has no image support";
  const BaseMesh mesh = test::shape(GetParam());
  const int level = 4;
  Atlas buffer(test::runtime(), mesh, level, AtlasStorage::Buffer);
  Atlas image(test::runtime(), mesh, level, AtlasStorage::Image);
  for (Atlas* a : {&buffer, &image}) {
    a->subdivide(1, level);
    a->compute_limit();
  }
  for (int l = 1; l <= level; ++l) {
    const auto b = buffer.read_positions(l), i = image.read_positions(l);
    ASSERT_EQ(b.size(), i.size());
    EXPECT_EQ(differing_texels(b, i), 0u) << "subdivided level " << l;
  }
  EXPECT_EQ(differing_texels(buffer.read_limit_positions(), image.read_limit_positions()), 0u);
  EXPECT_EQ(differing_texels(buffer.read_limit_normals(), image.read_limit_normals()), 0u);

  for (Atlas* a : {&buffer, &image})
    a->reduce(level, 1);
  for (int l = 1; l < level; ++l)
    EXPECT_EQ(differing_texels(buffer.read_positions(l), image.read_positions(l)), 0u) << "reduced level " << l;
}

TEST(StoragePaths, HostRoundTripKeepsPatchMajorOrder)
{
  if (!test::runtime()->info().images)
    GTEST_SKIP() << "no image support";
  const BaseMesh mesh = test::shape("mixed_polygons");
  Atlas image(test::runtime(), mesh, 3, AtlasStorage::Image);
  std::vector<Float4> texels(image.layout(3).texels());
  for (std::size_t t = 0; t < texels.size(); ++t)
    texels[t] = {float(t), float(t % 7), -float(t), 1.f};
  image.write_positions(3, texels);
  EXPECT_EQ(differing_texels(image.read_positions(3), texels), 0u);
}

INSTANTIATE_TEST_SUITE_P(Shapes, StoragePaths, testing::ValuesIn(test::shape_names()));

} // namespace
} // namespace meshpaint
