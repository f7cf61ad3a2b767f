// The fit's surface queries (CGAL's AABB tree) and the parallel loop the fit
// runs them in.
#include "core/parallel_for.h"
#include "project/aabb_surface_query.h"

#include <gtest/gtest.h>

#include <atomic>    // for std::atomic
#include <cmath>     // for std::sin, std::cos
#include <stdexcept> // for std::runtime_error
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

//! The unit square in z = 0 as two triangles, and a degenerate one.
std::unique_ptr<SurfaceQuery> square()
{
  const std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 2, 2}};
  return aabb_surface_queries()(points, {{0, 1, 2}, {0, 2, 3}, {4, 4, 4}});
}

TEST(SurfaceQuery, FindsTheClosestPointOnTheSurface)
{
  const auto q = square();
  const Vec3 above = q->closest_point({0.25f, 0.5f, 3.f});
  EXPECT_FLOAT_EQ(above[0], 0.25f);
  EXPECT_FLOAT_EQ(above[1], 0.5f);
  EXPECT_FLOAT_EQ(above[2], 0.f);
  const Vec3 outside = q->closest_point({2.f, 0.5f, 1.f}); // nearest the edge x = 1, not the degenerate point
  EXPECT_FLOAT_EQ(outside[0], 1.f);
  EXPECT_FLOAT_EQ(outside[1], 0.5f);
  EXPECT_FLOAT_EQ(outside[2], 0.f);
}

TEST(SurfaceQuery, NamesTheClosestTriangleAsGiven)
{
  const auto q = square();
  Vec3 closest{};
  EXPECT_EQ(q->closest_triangle({0.75f, 0.25f, 1.f}, closest), 0); // below the diagonal: (0, 1, 2)
  EXPECT_EQ(q->closest_triangle({0.25f, 0.75f, -1.f}, closest), 1); // above it: (0, 2, 3)
  EXPECT_FLOAT_EQ(closest[2], 0.f);
  EXPECT_LT(q->closest_triangle({2.f, 2.f, 2.f}, closest), 2); // the degenerate one (at 2, 2, 2) is never named
  const auto none = aabb_surface_queries()({{0, 0, 0}, {1, 1, 1}}, {{0, 1, 1}});
  EXPECT_EQ(none->closest_triangle({1.f, 0.f, 0.f}, closest), -1);
}

TEST(SurfaceQuery, HitsOnlyWithinTheSegment)
{
  const auto q = square();
  Vec3 hit{};
  ASSERT_TRUE(q->first_hit({0.5f, 0.25f, 1.f}, {0.5f, 0.25f, -1.f}, hit));
  EXPECT_FLOAT_EQ(hit[0], 0.5f);
  EXPECT_FLOAT_EQ(hit[1], 0.25f);
  EXPECT_FLOAT_EQ(hit[2], 0.f);
  EXPECT_FALSE(q->first_hit({0.5f, 0.25f, 1.f}, {0.5f, 0.25f, 0.5f}, hit)); // stops short of the surface
  EXPECT_FALSE(q->first_hit({0.5f, 0.25f, 1.f}, {0.5f, 0.25f, 2.f}, hit));  // points away
  EXPECT_FALSE(q->first_hit({3.f, 3.f, 1.f}, {3.f, 3.f, -1.f}, hit));       // passes beside
}

TEST(SurfaceQuery, AnswersTheSameFromManyThreads)
{
  const auto q = square();
  std::vector<Vec3> from;
  for (int k = 0; k < 20000; ++k)
    from.push_back({float(std::cos(k)) * 2.f, float(std::sin(k)) * 2.f, float(k % 7) - 3.f});
  std::vector<Vec3> serial(from.size()), threaded(from.size());
  for (std::size_t k = 0; k < from.size(); ++k)
    serial[k] = q->closest_point(from[k]);
  parallel_for(from.size(), 64, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      threaded[k] = q->closest_point(from[k]);
  });
  EXPECT_EQ(serial, threaded);
}

TEST(ParallelFor, CoversEveryIndexOnceAndPassesExceptionsOn)
{
  std::vector<std::atomic<int>> seen(10007);
  parallel_for(seen.size(), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      ++seen[k];
  });
  for (const auto& s : seen)
    ASSERT_EQ(s.load(), 1);
  EXPECT_THROW(parallel_for(1000, 1,
                            [](std::size_t begin, std::size_t) {
                              if (begin > 0)
                                throw std::runtime_error("a piece failed");
                            }),
               std::runtime_error);
}

} // namespace
} // namespace meshpaint
