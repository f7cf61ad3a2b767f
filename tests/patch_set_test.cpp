// The host's patch sets against their definitions from the patch corners
// alone: a patch's corner neighbourhood is every patch with a corner in
// common, and its outside bits are the sides and corners it shares with a
// patch not in the set. Sets of a few and of many patches take different
// ways through the set maker; both are checked.

#include "atlas/atlas.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <algorithm> // for std::sort, std::reverse
#include <cstdint>   // for std::uint8_t, std::uint32_t
#include <string>    // for std::string, std::to_string
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

class PatchSets : public testing::TestWithParam<std::string>
{
};

std::vector<int> sorted(std::vector<int> v)
{
  std::sort(v.begin(), v.end());
  return v;
}

void expect_sets_as_defined(const BaseMesh& mesh, const std::string& name)
{
  Atlas atlas(test::runtime(), mesh, 2, AtlasStorage::Buffer);
  const AtlasTopology& topo = atlas.topology();
  const int patches = topo.patch_count;
  std::vector<std::vector<int>> at(topo.rings.size()); // level-1 vertex -> the patches with a corner there
  for (int p = 0; p < patches; ++p)
    for (const int v : topo.patch_corners[std::size_t(p)])
      at[std::size_t(v)].push_back(p);
  std::uint32_t random = 12345;
  for (const int percent : {2, 5, 30, 70, 100}) {
    const std::string what = name + ", " + std::to_string(percent) + "%";
    // A spread of patches, one of them listed twice.
    std::vector<int> set;
    std::vector<bool> in(std::size_t(patches), false);
    for (int p = 0; p < patches; ++p) {
      random = random * 1664525u + 1013904223u;
      if (int(random >> 8) % 100 < percent || (set.empty() && p == patches - 1)) {
        set.push_back(p);
        in[std::size_t(p)] = true;
      }
    }
    std::reverse(set.begin(), set.end());
    const std::vector<int> once = set;
    set.push_back(set.front());

    std::vector<int> around;
    std::vector<bool> near(std::size_t(patches), false);
    for (const int p : set)
      for (const int v : topo.patch_corners[std::size_t(p)])
        for (const int q : at[std::size_t(v)])
          near[std::size_t(q)] = true;
    for (int q = 0; q < patches; ++q)
      if (near[std::size_t(q)])
        around.push_back(q);
    EXPECT_EQ(atlas.corner_neighbourhood(set), around) << what;

    const auto outside_bits = [&](int p) {
      std::uint8_t bits = 0;
      for (int c = 0; c < 4; ++c)
        for (const int q : at[std::size_t(topo.patch_corners[std::size_t(p)][std::size_t(c)])])
          if (!in[std::size_t(q)])
            bits |= std::uint8_t(16u << c);
      for (int s = 0; s < 4; ++s) {
        const int q = topo.across(p, s);
        if (q >= 0 && !in[std::size_t(q)])
          bits |= std::uint8_t(1u << s);
      }
      return bits;
    };
    std::vector<std::uint8_t> outside;
    for (const int p : set)
      outside.push_back(outside_bits(p));
    EXPECT_EQ(atlas.shared_outside(set), outside) << what << ", a patch listed twice";
    outside.pop_back();
    EXPECT_EQ(atlas.shared_outside(once), outside) << what;

    // By Reach::All, the sides and corners shared with no patch outside.
    const PatchSet all = atlas.patch_set(set, Reach::All);
    std::vector<int> listed, edges, corners;
    for (int p = 0; p < patches; ++p)
      if (in[std::size_t(p)])
        listed.push_back(p);
    EXPECT_EQ(all.patches, listed) << what;
    std::vector<bool> edge_in(topo.edges.size(), false), corner_in(topo.rings.size(), false);
    for (std::size_t k = 0; k < listed.size(); ++k) {
      const int p = listed[k];
      const std::uint8_t bits = outside_bits(p);
      ASSERT_EQ(all.outside[k], bits) << what << ", patch " << p;
      for (int s = 0; s < 4; ++s) {
        const int e = topo.patch_sides[std::size_t(p)][std::size_t(s)];
        const int v = topo.patch_corners[std::size_t(p)][std::size_t(s)];
        if (!(bits >> s & 1) && !edge_in[std::size_t(e)]) {
          edge_in[std::size_t(e)] = true;
          edges.push_back(e);
        }
        if (!(bits >> (4 + s) & 1) && !corner_in[std::size_t(v)]) {
          corner_in[std::size_t(v)] = true;
          corners.push_back(v);
        }
      }
    }
    EXPECT_EQ(sorted(all.edges), sorted(edges)) << what;
    EXPECT_EQ(sorted(all.corners), sorted(corners)) << what;
    ASSERT_EQ(all.rings.size(), all.corners.size()) << what;
    for (std::size_t k = 0; k < all.rings.size(); ++k)
      EXPECT_EQ(all.rings[k], atlas.tables().device_ring(all.corners[k])) << what;
  }
}

TEST_P(PatchSets, NeighbourhoodsAndSharedPartsMatchTheirDefinitions)
{
  expect_sets_as_defined(test::shape(GetParam()), GetParam());
}

TEST(PatchSets, LargeMeshesMatchTheirDefinitions)
{
  // Thousands of patches, so that the sets of 2% and 5% take the way of a
  // few patches: a grid with its border, and a closed sphere.
  expect_sets_as_defined(test::flat_grid(40), "grid");
  expect_sets_as_defined(test::noisy_sphere(24, 0.f), "sphere");
}

INSTANTIATE_TEST_SUITE_P(Shapes, PatchSets, testing::ValuesIn(test::shape_names()));

} // namespace
} // namespace meshpaint
