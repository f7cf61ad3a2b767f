// The two atlas storage paths (linear buffers, image2d objects) run the same
// kernel source and must give the same bits for every operation; so must
// the two ways of taking the corners of several subdivision steps, and
// the reductions per side and per texel.

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

// On CPUs the corners of every step come from one gather of the first
// level's rings; a corner kernel per step (the GPUs' way) must give the same
// bits. Level 5 takes the rings three steps beyond the first.
void expect_corner_paths_agree(const BaseMesh& mesh)
{
  const int level = 5;
  Atlas one_pass(test::runtime(), mesh, level, AtlasStorage::Buffer);
  Atlas per_step(test::runtime(), mesh, level, AtlasStorage::Buffer);
  per_step.set_patch_items(false);
  if (!one_pass.evaluator().corners_in_one_pass())
    GTEST_SKIP() << test::runtime()->info().name << " runs a corner kernel per step";
  ASSERT_FALSE(per_step.evaluator().corners_in_one_pass());
  for (Atlas* a : {&one_pass, &per_step})
    a->subdivide(1, level);
  for (int l = 2; l <= level; ++l)
    EXPECT_EQ(differing_texels(one_pass.read_positions(l), per_step.read_positions(l)), 0u) << "level " << l;
  // From a level above the first, as multiresolution edits subdivide.
  for (Atlas* a : {&one_pass, &per_step})
    a->subdivide(2, level);
  EXPECT_EQ(differing_texels(one_pass.read_positions(level), per_step.read_positions(level)), 0u) << "from level 2";
}

TEST_P(StoragePaths, CornersInOnePassAgreeWithACornerKernelPerStep)
{
  expect_corner_paths_agree(test::shape(GetParam()));
}

// CPUs take the steps from levels 1 and 2 with tile kernels that walk their
// own sides (no side kernel), for every patch and for a listed set. The
// side kernel's bits either way.
TEST_P(StoragePaths, TilesWalkingTheirSidesAgreeWithASideKernel)
{
  const BaseMesh mesh = test::shape(GetParam());
  const int level = 4;
  Atlas walks(test::runtime(), mesh, level, AtlasStorage::Buffer);
  Atlas sides(test::runtime(), mesh, level, AtlasStorage::Buffer);
  walks.set_patch_items(true);
  sides.set_patch_items(false);
  ASSERT_TRUE(walks.evaluator().tiles_walk_sides(1) && walks.evaluator().tiles_walk_sides(2));
  ASSERT_FALSE(walks.evaluator().tiles_walk_sides(3) || sides.evaluator().tiles_walk_sides(1));
  for (Atlas* a : {&walks, &sides})
    a->subdivide(1, level);
  for (int l = 2; l <= level; ++l)
    EXPECT_EQ(differing_texels(walks.read_positions(l), sides.read_positions(l)), 0u) << "level " << l;

  // Move level 1 (every copy of a vertex alike), then subdivide it as a
  // listed set of every patch, last first.
  std::vector<Float4> first = walks.read_positions(1);
  for (Float4& t : first)
    t[0] = 1.5f * t[0] + 0.25f * t[1];
  std::vector<int> every;
  for (int p = walks.layout(1).patches - 1; p >= 0; --p)
    every.push_back(p);
  for (Atlas* a : {&walks, &sides}) {
    a->write_positions(1, first);
    a->subdivide(1, 3, a->patch_set(every, Reach::Any));
  }
  for (int l = 2; l <= 3; ++l)
    EXPECT_EQ(differing_texels(walks.read_positions(l), sides.read_positions(l)), 0u) << "set, level " << l;
}

// CPUs run the reduction's sides as one work item walking each (and the
// tile kernels per patch); GPUs a work item per texel. Both the same bits,
// at every level a reduction from level 5 passes.
TEST_P(StoragePaths, ReductionPerSideAgreesWithPerTexel)
{
  const BaseMesh mesh = test::shape(GetParam());
  const int level = 5;
  Atlas walks(test::runtime(), mesh, level, AtlasStorage::Buffer);
  Atlas texels(test::runtime(), mesh, level, AtlasStorage::Buffer);
  walks.set_patch_items(true);
  texels.set_patch_items(false);
  for (Atlas* a : {&walks, &texels}) {
    a->subdivide(1, level);
    a->reduce(level, 1);
  }
  for (int l = 1; l < level; ++l)
    EXPECT_EQ(differing_texels(walks.read_positions(l), texels.read_positions(l)), 0u) << "reduced level " << l;
  // A reduction that starts at level 2 takes its sectors from the tiles
  // (reduce_sectors), one from further up from the step into level 2.
  for (Atlas* a : {&walks, &texels}) {
    a->subdivide(1, 2);
    a->reduce(2, 1);
  }
  EXPECT_EQ(differing_texels(walks.read_positions(1), texels.read_positions(1)), 0u) << "level 1 reduced from 2";
}

// Signed zeros: the one-pass kernel cannot see the zero-weighted taps that
// decide the sign of a zero sum, and must leave those rings to the levels
// themselves. A grid whose z is -0 on one half and rises on the other.
TEST(StoragePaths, CornersInOnePassKeepTheSignOfZeros)
{
  const int n = 8;
  std::vector<Vec3> pts;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x)
      pts.push_back({float(x), float(y), x > n / 2 ? 0.01f * float(x - n / 2) : -0.0f});
  std::vector<std::vector<int>> faces;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      faces.push_back({y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1, (y + 1) * (n + 1) + x});
  expect_corner_paths_agree(make_base_mesh(pts, faces, "signed_zeros"));
}

// Rings of more slots than the one-pass kernel holds are taken from the
// levels: a pyramid over a 40-gon (apex and base centre of valence 40).
TEST(StoragePaths, CornersInOnePassLeaveWideRingsToEachLevel)
{
  const int valence = 40;
  static_assert(valence > RING_LEVELS_MAX, "the ring must be too wide for one pass");
  expect_corner_paths_agree(test::high_valence(valence));
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

std::vector<Float4> read_bounds(Atlas& atlas)
{
  std::vector<Float4> out(std::size_t(atlas.topology().patch_count));
  atlas.runtime().queue().enqueueReadBuffer(atlas.limit_bounds(), CL_TRUE, 0, out.size() * sizeof(Float4), out.data());
  return out;
}

// CPUs take the limit's tiles a work item per patch (limit_patches), GPUs a
// work item per texel (limit_tiles). The same bits for the whole surface
// and for sets as host lists and as device flags, with some patches
// collapsed to a point, whose normals take normalize()'s own way.
TEST_P(StoragePaths, LimitPerPatchAgreesWithPerTexel)
{
  const BaseMesh mesh = test::shape(GetParam());
  std::vector<AtlasStorage> storages = {AtlasStorage::Buffer};
  if (test::runtime()->info().images)
    storages.push_back(AtlasStorage::Image);
  for (const AtlasStorage storage : storages)
    for (const int level : {2, 3, 4}) {
      const std::string what = std::string(storage == AtlasStorage::Image ? "image" : "buffer") + ", level " +
                               std::to_string(level);
      Atlas walks(test::runtime(), mesh, level, storage);
      Atlas texels(test::runtime(), mesh, level, storage);
      walks.set_patch_items(true);
      texels.set_patch_items(false);
      const int patches = walks.topology().patch_count;
      for (const bool flags : {false, true}) {
        for (Atlas* a : {&walks, &texels}) {
          a->subdivide(1, level);
          a->compute_limit();
          // Inside every fifth tile the points move, inside every tenth
          // they all go to one point.
          std::vector<Float4> x = a->read_positions(level);
          const LevelLayout l = a->layout(level);
          std::vector<int> changed;
          for (int p = 0; p < patches; p += 5) {
            changed.push_back(p);
            const auto at = [&](int i, int j) -> Float4& { return x[std::size_t((p * l.tile + j) * l.tile + i)]; };
            for (int j = 1; j < l.n; ++j)
              for (int i = 1; i < l.n; ++i)
                if (p % 10 == 0)
                  at(i, j) = at(1, 1);
                else
                  at(i, j)[1] += 0.01f * float((i + 2 * j) % 3);
          }
          a->write_positions(level, x);
          a->assume_limit_current();
          a->set_device_set_share(flags ? std::size_t(patches) : 0);
          a->update_limit(a->neighbourhood(changed));
        }
        const std::string form = what + (flags ? ", flags" : ", lists");
        EXPECT_EQ(differing_texels(walks.read_limit_positions(), texels.read_limit_positions()), 0u) << form;
        EXPECT_EQ(differing_texels(walks.read_limit_normals(), texels.read_limit_normals()), 0u) << form;
        EXPECT_EQ(differing_texels(read_bounds(walks), read_bounds(texels)), 0u) << form;
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, StoragePaths, testing::ValuesIn(test::shape_names()));

} // namespace
} // namespace meshpaint
