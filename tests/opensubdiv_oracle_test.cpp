// The atlas kernels against OpenSubdiv: every vertex of every level, and the
// limit positions and normals, on shapes covering each Catmull-Clark rule and
// on the Stanford bunny.

#include "atlas/atlas.h"
#include "atlas/weld.h"
#include "reference/opensubdiv_reference.h"
#include "support/copies.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cmath>   // for std::acos, std::sqrt

namespace meshpaint {
namespace {

struct Case
{
  std::string shape;
  int level;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.shape << " at level " << c.level; }

std::string case_name(const testing::TestParamInfo<Case>& info)
{
  return info.param.shape + "_level" + std::to_string(info.param.level);
}

double distance(const Vec3& a, const Vec3& b)
{
  double d2 = 0;
  for (int k = 0; k < 3; ++k)
    d2 += double(a[k] - b[k]) * double(a[k] - b[k]);
  return std::sqrt(d2);
}

double angle_degrees(const Vec3& a, const Vec3& b)
{
  double dot = 0, la = 0, lb = 0;
  for (int k = 0; k < 3; ++k) {
    dot += double(a[k]) * b[k];
    la += double(a[k]) * a[k];
    lb += double(b[k]) * b[k];
  }
  const double c = dot / std::sqrt(la * lb);
  return std::acos(c > 1 ? 1 : c < -1 ? -1 : c) * 180.0 / M_PI;
}

BaseMesh load_case_mesh(const std::string& name)
{
  if (name != "bunny")
    return test::shape(name);
  const std::string path = test::scan_path("bunny00.off");
  if (path.empty())
    throw std::runtime_error("data/scans/bunny00.off is missing: run scripts/fetch-scans.sh");
  return load_mesh(path);
}

class OpenSubdivOracle : public testing::TestWithParam<Case>
{
};

TEST_P(OpenSubdivOracle, LevelAndLimitMatch)
{
  const Case c = GetParam();
  const BaseMesh mesh = load_case_mesh(c.shape);
  const double tol = 1e-5 * mesh.diagonal();

  Atlas atlas(test::runtime(), mesh, c.level, AtlasStorage::Buffer);
  atlas.subdivide(1, c.level);
  atlas.compute_limit();
  const LevelLayout layout = atlas.layout(c.level);
  const auto texels = atlas.read_positions(c.level);
  const auto limit_pos = atlas.read_limit_positions();
  const auto limit_nrm = atlas.read_limit_normals();
  // Every stored copy of a patch-side or corner vertex holds the same bits.
  EXPECT_EQ(test::differing_copies(atlas.topology(), layout, texels), 0u) << "positions";
  EXPECT_EQ(test::differing_copies(atlas.topology(), layout, limit_pos), 0u) << "limit positions";
  EXPECT_EQ(test::differing_copies(atlas.topology(), layout, limit_nrm), 0u) << "limit normals";

  const WeldedSurface ours = weld(atlas.topology(), layout, texels, nullptr);
  const WeldedSurface limit = weld(atlas.topology(), layout, limit_pos, &limit_nrm);
  // The atlas works on the mesh with faces in spatial order; so does the oracle.
  const ReferenceLevel ref = opensubdiv_level(atlas.base_mesh(), c.level, true);
  const std::vector<int> order = opensubdiv_vertex_order(atlas.base_mesh(), atlas.topology(), c.level);
  ASSERT_EQ(ours.points.size(), ref.points.size()) << "vertex count differs from OpenSubdiv's";

  double worst_pos = 0, worst_limit = 0, worst_angle = 0;
  for (std::size_t v = 0; v < ours.points.size(); ++v) {
    ASSERT_GE(order[v], 0);
    worst_pos = std::max(worst_pos, distance(ours.points[v], ref.points[order[v]]));
    worst_limit = std::max(worst_limit, distance(limit.points[v], ref.limit_points[order[v]]));
    worst_angle = std::max(worst_angle, angle_degrees(limit.normals[v], ref.limit_normals[order[v]]));
  }
  EXPECT_LE(worst_pos, tol) << "level points";
  EXPECT_LE(worst_limit, tol) << "limit points";
  EXPECT_LE(worst_angle, 0.05) << "limit normals (degrees)";
  RecordProperty("worst_position_over_diagonal", std::to_string(worst_pos / mesh.diagonal()));
  RecordProperty("worst_normal_degrees", std::to_string(worst_angle));
}

std::vector<Case> cases()
{
  std::vector<Case> out;
  for (const std::string& s : test::shape_names())
    for (int level = 1; level <= 4; ++level)
      out.push_back({s, level});
  for (int level = 1; level <= 3; ++level)
    out.push_back({"bunny", level});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Shapes, OpenSubdivOracle, testing::ValuesIn(cases()), case_name);

} // namespace
} // namespace meshpaint
