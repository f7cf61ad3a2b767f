// Brush spaces: where a dab measures its distance (object, tangent, screen,
// parameter), the back-face policy, and screen strokes ending at silhouettes.

#include "atlas/weld.h"
#include "mesh/base_mesh.h"
#include "paint/paint_surface.h"
#include "support/copies.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <array>    // for std::array
#include <cmath>    // for std::sqrt, std::sin, std::cos
#include <cstdio>   // for std::printf
#include <cstring>  // for std::memcmp
#include <iterator> // for std::size
#include <set>      // for std::set
#include <string>   // for std::string

namespace meshpaint {
namespace {

Vec3 xyz(const Float4& t) { return {t[0], t[1], t[2]}; }

Stroke red_dab(const Vec3& at, float radius, int space)
{
  Stroke s;
  s.points = {at};
  s.brush.radius = radius;
  s.brush.falloff = FALLOFF_CONSTANT;
  s.brush.space = space;
  s.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  return s;
}

bool red(const Float4& d) { return d[0] == 1.f && d[1] == 0.f; }

//! Checks that exactly the texels whose `distance` is below 1 - margin are
//! painted, none above 1 + margin; returns how many are painted.
template <typename F>
std::size_t expect_footprint(PaintSurface& surface, F distance, double margin = 0.02)
{
  const std::vector<Float4> pos = surface.atlas().read_limit_positions();
  const std::vector<Float4> diffuse = surface.read_channels().diffuse;
  std::size_t painted = 0, wrong = 0;
  for (std::size_t t = 0; t < pos.size(); ++t) {
    const double d = distance(t, xyz(pos[t]));
    if (red(diffuse[t]))
      ++painted;
    if ((d < 1 - margin && !red(diffuse[t])) || (d > 1 + margin && red(diffuse[t])))
      ++wrong;
  }
  EXPECT_EQ(wrong, 0u) << painted << " painted";
  return painted;
}

TEST(BrushSpace, ObjectIsABallAndTangentACylinderOnASphere)
{
  const Vec3 top{0.f, 0.f, 1.f};
  const float r = 0.8f;
  for (const int space : {SPACE_OBJECT, SPACE_TANGENT}) {
    SCOPED_TRACE(space);
    PaintSurface surface(test::runtime(), test::noisy_sphere(4, 0.f), 4, AtlasStorage::Buffer);
    surface.apply(red_dab(top, r, space));
    // The brush centre: the surface point closest to `top`, on the z axis.
    Vec3 c = top;
    for (const Float4& t : surface.atlas().read_limit_positions())
      if (dot(sub(xyz(t), top), sub(xyz(t), top)) < dot(sub(c, top), sub(c, top)) || c == top)
        c = xyz(t);
    const std::size_t n = expect_footprint(surface, [&](std::size_t, const Vec3& x) {
      if (space == SPACE_OBJECT)
        return std::sqrt(double(dot(sub(x, c), sub(x, c)))) / r;
      return x[2] < 0.f ? 10.0 : std::sqrt(double(x[0]) * x[0] + double(x[1]) * x[1]) / r;
    });
    EXPECT_GT(n, 100u) << "space " << space;
  }
}

//! A camera 20 units from (4, 4, 0), looking at it 60 degrees off the normal
//! of the z = 0 plane.
Camera oblique_camera()
{
  Camera c;
  const double a = 60.0 * M_PI / 180.0;
  c.focal_point = {4.f, 4.f, 0.f};
  c.position = {4.f, float(4.0 - 20.0 * std::sin(a)), float(20.0 * std::cos(a))};
  c.view_up = {0.f, 0.f, 1.f};
  c.view_angle = 30.f;
  return c;
}

TEST(BrushSpace, ScreenIsTheDiscSeenFromTheCamera)
{
  PaintSurface surface(test::runtime(), test::flat_grid(8), 4, AtlasStorage::Buffer);
  const Vec3 centre{4.f, 4.f, 0.f};
  const float r = 0.8f;
  Stroke s = red_dab(centre, r, SPACE_SCREEN);
  s.brush.camera = oblique_camera();
  s.brush.has_camera = true;
  surface.apply(s);
  // The same projection as the kernel: screen offset at the centre's depth.
  const Vec3 eye = s.brush.camera.position, dir = normalized(sub(s.brush.camera.focal_point, eye)),
             right = normalized(cross(dir, s.brush.camera.view_up)), up = cross(right, dir);
  const auto screen = [&](const Vec3& x, float& z) {
    const Vec3 v = sub(x, eye);
    z = dot(v, dir);
    return std::array<float, 2>{dot(v, right) / z, dot(v, up) / z};
  };
  float zc;
  const auto sc = screen(centre, zc);
  expect_footprint(surface, [&](std::size_t, const Vec3& x) {
    float z;
    const auto s2 = screen(x, z);
    return std::hypot(double(s2[0] - sc[0]), double(s2[1] - sc[1])) * zc / r;
  });
  // Foreshortened by cos 60: the footprint reaches twice as far along y.
  const std::vector<Float4> pos = surface.atlas().read_limit_positions();
  const std::vector<Float4> diffuse = surface.read_channels().diffuse;
  float far_y = 0.f, far_x = 0.f;
  for (std::size_t t = 0; t < pos.size(); ++t)
    if (red(diffuse[t])) {
      far_y = std::max(far_y, std::fabs(pos[t][1] - 4.f));
      far_x = std::max(far_x, std::fabs(pos[t][0] - 4.f));
    }
  EXPECT_NEAR(far_x, r, 0.1 * r);
  EXPECT_NEAR(far_y, 2 * r, 0.15 * r);
}

TEST(BrushSpace, ParameterIsASquareOfTexelsInThePatchUnderTheCentre)
{
  PaintSurface surface(test::runtime(), test::flat_grid(8), 4, AtlasStorage::Buffer);
  // Level 4: patches of 0.5 x 0.5 with 8 x 8 faces, texels 0.0625 apart; the
  // centre on a texel in the middle of a patch.
  surface.apply(red_dab({4.25f, 4.25f, 0.f}, 0.15f, SPACE_PARAMETER));
  const LevelLayout l = surface.atlas().layout(4);
  const std::vector<Float4> diffuse = surface.read_channels().diffuse;
  const std::vector<Float4> pos = surface.atlas().read_limit_positions();
  std::size_t painted = 0;
  int patch = -1;
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.tile; ++j)
      for (int i = 0; i < l.tile; ++i)
        if (red(diffuse[l.index(p, i, j)])) {
          ++painted;
          EXPECT_TRUE(patch < 0 || patch == p);
          patch = p;
          const Float4& x = pos[l.index(p, i, j)];
          EXPECT_LE(std::max(std::fabs(x[0] - 4.25f), std::fabs(x[1] - 4.25f)), 0.15f);
        }
  EXPECT_EQ(painted, 25u); // 5 x 5 texels: a square, not a disc
}

//! What a dab painted: the welded vertices and the patches with painted texels.
struct Painted
{
  std::set<int> vertices, patches;
};

Painted painted_parts(PaintSurface& surface, const std::vector<Float4>& diffuse)
{
  const LevelLayout l = surface.atlas().layout(surface.level());
  const std::vector<int> weld = weld_map(surface.atlas().topology(), l);
  Painted out;
  for (int p = 0; p < l.patches; ++p)
    for (int j = 0; j < l.tile; ++j)
      for (int i = 0; i < l.tile; ++i)
        if (red(diffuse[l.index(p, i, j)])) {
          out.vertices.insert(weld[l.index(p, i, j)]);
          out.patches.insert(p);
        }
  return out;
}

TEST(BrushSpace, ParameterSquaresContinueAcrossPatchSides)
{
  // Level 4 on a flat grid: patches of 0.5 x 0.5, texels 0.0625 apart, the
  // limit surface affine away from the border, neighbouring patches turned
  // against each other. Patch corners lie at multiples of 0.5, all of valence 4.
  struct Case
  {
    const char* what;
    Vec3 centre;
    float radius;
    int half;             // texels from the centre to the square's side
    std::size_t patches;  // with painted texels
  };
  const Case cases[] = {
    {"one texel from a side", {4.0625f, 4.25f, 0.f}, 0.15f, 2, 2},
    {"around a corner", {4.0625f, 4.0625f, 0.f}, 0.15f, 2, 4},
    {"on a corner", {4.f, 4.f, 0.f}, 0.15f, 2, 4},
    {"wider than a patch", {4.0625f, 4.1875f, 0.f}, 0.7f, 11, 16},
  };
  const float texel = 0.0625f;
  std::vector<std::vector<Float4>> first; // per case, under the first storage
  for (const AtlasStorage storage : test::storages())
    for (std::size_t k = 0; k < std::size(cases); ++k) {
      const Case& c = cases[k];
      SCOPED_TRACE(std::string(c.what) + (storage == AtlasStorage::Image ? ", images" : ", buffers"));
      PaintSurface surface(test::runtime(), test::flat_grid(8), 4, storage);
      surface.apply(red_dab(c.centre, c.radius, SPACE_PARAMETER));
      const std::vector<Float4> diffuse = surface.read_channels().diffuse;
      if (first.size() == k)
        first.push_back(diffuse);
      else // both storages give the same bits
        EXPECT_EQ(std::memcmp(first[k].data(), diffuse.data(), sizeof(Float4) * diffuse.size()), 0);
      EXPECT_EQ(test::differing_copies(surface.atlas().topology(), surface.atlas().layout(4), diffuse), 0u);
      // Exactly the texels within `half` texels in both directions.
      const std::vector<Float4> pos = surface.atlas().read_limit_positions();
      std::size_t wrong = 0;
      for (std::size_t t = 0; t < pos.size(); ++t) {
        const float d = std::max(std::fabs(pos[t][0] - c.centre[0]), std::fabs(pos[t][1] - c.centre[1])) / texel;
        wrong += red(diffuse[t]) != (d < float(c.half) + 0.5f);
      }
      EXPECT_EQ(wrong, 0u);
      const Painted painted = painted_parts(surface, diffuse);
      EXPECT_EQ(painted.vertices.size(), std::size_t((2 * c.half + 1) * (2 * c.half + 1)));
      EXPECT_EQ(painted.patches.size(), c.patches);
    }
}

//! The engine's texel size on patch p: the side of the square in the
//! sphere around the patch's bounding box, over its texels.
float texel_size(const std::vector<Float4>& pos, const LevelLayout& l, int p)
{
  Vec3 lo = xyz(pos[l.index(p, 0, 0)]), hi = lo;
  for (int j = 0; j < l.tile; ++j)
    for (int i = 0; i < l.tile; ++i)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], pos[l.index(p, i, j)][k]);
        hi[k] = std::max(hi[k], pos[l.index(p, i, j)][k]);
      }
  const Vec3 mid{0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1]), 0.5f * (lo[2] + hi[2])};
  float bound = 0.f;
  for (int j = 0; j < l.tile; ++j)
    for (int i = 0; i < l.tile; ++i) {
      const Vec3 d = sub(xyz(pos[l.index(p, i, j)]), mid);
      bound = std::max(bound, std::sqrt(dot(d, d)));
    }
  return std::sqrt(2.f) * bound / float(l.n);
}

TEST(BrushSpace, ParameterSquaresAtExtraordinaryVertices)
{
  // A cube's corner, where three patches meet, and a pyramid's apex, where
  // twelve do. Each patch around the vertex is laid with the vertex at the
  // centre, so the dab centred there gets the corner block of each: at
  // valence 3 three quarters of the square, at 12 the blocks overlap.
  struct Case
  {
    const char* shape;
    Vec3 towards; // the vertex is the surface's furthest point this way
    int valence;
  };
  const int level = 4, half = 2;
  for (const Case& v : {Case{"cube", {1.f, 1.f, 1.f}, 3}, Case{"high_valence", {0.f, 0.f, 1.f}, 12}})
    for (const AtlasStorage storage : test::storages()) {
      SCOPED_TRACE(std::string(v.shape) + (storage == AtlasStorage::Image ? ", images" : ", buffers"));
      PaintSurface surface(test::runtime(), test::shape(v.shape), level, storage);
      const LevelLayout l = surface.atlas().layout(level);
      const AtlasTopology& topo = surface.atlas().topology();
      const std::vector<Float4> pos = surface.atlas().read_limit_positions();
      // The vertex's texel in its lowest patch: the dab's centre patch.
      std::size_t corner = 0;
      for (std::size_t t = 0; t < pos.size(); ++t)
        if (dot(xyz(pos[t]), v.towards) > dot(xyz(pos[corner]), v.towards))
          corner = t;
      const int p = int(corner / (std::size_t(l.tile) * l.tile));
      const float texel = texel_size(pos, l, p);
      surface.apply(red_dab(xyz(pos[corner]), (float(half) + 0.5f) * texel, SPACE_PARAMETER));

      const std::vector<Float4> diffuse = surface.read_channels().diffuse;
      EXPECT_EQ(test::differing_copies(topo, l, diffuse), 0u);
      // In each patch at the vertex, texel (a, b) of the corner's frame (a
      // along the corner's outgoing side, b along its incoming one) is painted
      // when both are within `half`; nothing else is.
      const int ij = int(corner % (std::size_t(l.tile) * l.tile));
      const int i0 = ij % l.tile, j0 = ij / l.tile;
      const int c = j0 == 0 ? (i0 == 0 ? 0 : 1) : (i0 == 0 ? 3 : 2);
      const CornerRing& ring = topo.rings[std::size_t(topo.patch_corners[std::size_t(p)][c])];
      ASSERT_EQ(ring.count, v.valence);
      const int unit[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
      std::size_t in_block = 0, wrong = 0;
      for (int k = 0; k < ring.count; ++k) {
        const CornerSlot& slot = topo.slots[std::size_t(ring.first + k)];
        const int* o = unit[slot.corner];
        const int *dt = dir[slot.corner], *dd = dir[(slot.corner + 1) % 4];
        for (int b = 0; b <= l.n; ++b)
          for (int a = 0; a <= l.n; ++a) {
            const bool painted = red(diffuse[l.index(slot.patch, o[0] * l.n + a * dt[0] + b * dd[0],
                                                      o[1] * l.n + a * dt[1] + b * dd[1])]);
            wrong += painted != (a <= half && b <= half);
            in_block += painted;
          }
      }
      EXPECT_EQ(wrong, 0u);
      EXPECT_EQ(in_block, std::size_t(v.valence * (half + 1) * (half + 1)));
      // Blocks of 3 x 3 sharing their sides in pairs and the corner by all.
      const Painted painted = painted_parts(surface, diffuse);
      EXPECT_EQ(painted.vertices.size(), std::size_t(v.valence * (9 - 3) + 1));
    }
}

TEST(BrushSpace, ParameterDabsOnATriangleScanPaintAboutTheRadius)
{
  // Each triangle of a scan makes three patches around a vertex of valence
  // 3, joined about six round each of its corners: unfolded, their tiles
  // leave quarters of the plane empty and overlap elsewhere. A dab of the
  // usual size spans some twelve tiles each way from its centre.
  const std::string path = test::scan_path("bunny00.off");
  ASSERT_FALSE(path.empty()) << "data/scans/bunny00.off is missing: run scripts/fetch-scans.sh";
  const BaseMesh mesh = load_mesh(path);
  const float radius = 0.03f * float(mesh.diagonal());
  const Vec3 at = mesh.points[mesh.points.size() / 3];
  const int level = 2;
  std::vector<Float4> first;
  for (const AtlasStorage storage : test::storages()) {
    SCOPED_TRACE(storage == AtlasStorage::Image ? "images" : "buffers");
    PaintSurface object(test::runtime(), mesh, level, storage);
    object.apply(red_dab(at, radius, SPACE_OBJECT));
    const std::size_t ball = painted_parts(object, object.read_channels().diffuse).vertices.size();

    PaintSurface surface(test::runtime(), mesh, level, storage);
    surface.apply(red_dab(at, radius, SPACE_PARAMETER));
    const std::vector<Float4> diffuse = surface.read_channels().diffuse;
    const std::vector<Float4> pos = surface.atlas().read_limit_positions();
    const LevelLayout l = surface.atlas().layout(level);
    EXPECT_EQ(test::differing_copies(surface.atlas().topology(), l, diffuse), 0u);
    if (first.empty())
      first = diffuse;
    else // both storages give the same bits
      EXPECT_EQ(std::memcmp(first.data(), diffuse.data(), sizeof(Float4) * diffuse.size()), 0);

    // About the object-space dab's area, near the centre, and on many
    // patches: the square goes on across their sides.
    const Painted painted = painted_parts(surface, diffuse);
    EXPECT_GT(painted.vertices.size(), ball / 2);
    EXPECT_LT(painted.vertices.size(), ball * 2);
    // The centre: the closest texel, as the dab snaps to it.
    std::size_t centre = 0;
    for (std::size_t t = 0; t < pos.size(); ++t)
      if (dot(sub(xyz(pos[t]), at), sub(xyz(pos[t]), at)) < dot(sub(xyz(pos[centre]), at), sub(xyz(pos[centre]), at)))
        centre = t;
    float furthest = 0.f;
    for (std::size_t t = 0; t < pos.size(); ++t)
      if (red(diffuse[t]))
        furthest = std::max(furthest, length(sub(xyz(pos[t]), xyz(pos[centre]))));
    EXPECT_LT(furthest, 2.f * radius);
    const float half = radius / texel_size(pos, l, int(centre / (std::size_t(l.tile) * l.tile)));
    EXPECT_GT(half, 4.f * float(l.n)); // the square spans several tiles
    EXPECT_GT(painted.patches.size(), std::size_t(half / float(l.n) * half / float(l.n)));
  }
}

TEST(BrushSpace, ParameterSculptAtACoarseLevelKeepsCopiesIdentical)
{
  // A square across the corner of four patches, moving level 2's control
  // points: every patch under it moves, and the finest level's copies agree.
  PaintSurface surface(test::runtime(), test::flat_grid(8), 4, AtlasStorage::Buffer);
  const std::vector<Float4> before = surface.atlas().read_positions(4);
  const Stroke dab = red_dab({4.f, 4.f, 0.f}, 0.3f, SPACE_PARAMETER);
  Stroke s = make_stroke(Tool::Sculpt);
  s.points = dab.points;
  s.brush = dab.brush;
  s.move().amount = 0.2f;
  s.set_edit_level(2);
  surface.apply(s);
  const std::vector<Float4> after = surface.atlas().read_positions(4);
  const LevelLayout l = surface.atlas().layout(4);
  EXPECT_EQ(test::differing_copies(surface.atlas().topology(), l, after), 0u);
  std::set<int> moved;
  for (std::size_t t = 0; t < after.size(); ++t)
    if (after[t][2] != before[t][2])
      moved.insert(int(t / (std::size_t(l.tile) * l.tile)));
  EXPECT_GE(moved.size(), 4u);
}

TEST(BrushSpace, BackFacesAreSkippedUnlessAsked)
{
  Camera above;
  above.position = {0.f, 0.f, 10.f};
  above.view_up = {0.f, 1.f, 0.f};
  for (const bool backfaces : {false, true}) {
    PaintSurface surface(test::runtime(), test::noisy_sphere(4, 0.f), 3, AtlasStorage::Buffer);
    Stroke s = red_dab({0.f, 0.f, 1.f}, 1.2f, SPACE_SCREEN);
    s.brush.camera = above;
    s.brush.has_camera = true;
    s.brush.paint_backfaces = backfaces;
    surface.apply(s);
    const std::vector<Float4> pos = surface.atlas().read_limit_positions();
    const std::vector<Float4> diffuse = surface.read_channels().diffuse;
    std::size_t front = 0, back = 0;
    for (std::size_t t = 0; t < pos.size(); ++t)
      if (red(diffuse[t]))
        ++(pos[t][2] > 0.05f ? front : pos[t][2] < -0.05f ? back : front);
    EXPECT_GT(front, 500u);
    if (backfaces)
      EXPECT_GT(back, 500u);
    else
      EXPECT_EQ(back, 0u);
  }
}

TEST(BrushSpace, ScreenStrokesEndAtTheSilhouette)
{
  PaintSurface surface(test::runtime(), test::noisy_sphere(4, 0.f), 3, AtlasStorage::Buffer);
  Stroke s = red_dab({0.f, 0.f, 1.f}, 0.1f, SPACE_SCREEN);
  s.brush.camera.position = {0.f, 0.f, 10.f};
  s.brush.has_camera = true;
  for (int k = 1; k <= 12; ++k) { // over the side of the sphere and on to its back
    const double a = k * 15.0 * M_PI / 180.0;
    s.points.push_back({float(std::sin(a)), 0.f, float(std::cos(a))});
  }
  const StrokeReport report = surface.apply(s);
  EXPECT_TRUE(report.left_surface);
  const std::vector<Float4> pos = surface.atlas().read_limit_positions();
  const std::vector<Float4> diffuse = surface.read_channels().diffuse;
  for (std::size_t t = 0; t < pos.size(); ++t)
    if (red(diffuse[t]))
      ASSERT_GT(pos[t][2], -0.01f);
  // In object space the same path goes on round the back.
  PaintSurface object(test::runtime(), test::noisy_sphere(4, 0.f), 3, AtlasStorage::Buffer);
  s.brush.space = SPACE_OBJECT;
  s.brush.has_camera = false;
  EXPECT_FALSE(object.apply(s).left_surface);
}

//! Red texels in front (z > 0.05) and behind (z < -0.05) of the z = 0 plane.
std::array<std::size_t, 2> red_front_and_back(PaintSurface& surface)
{
  const std::vector<Float4> pos = surface.atlas().read_limit_positions();
  const std::vector<Float4> diffuse = surface.read_channels().diffuse;
  std::array<std::size_t, 2> n{0, 0};
  for (std::size_t t = 0; t < pos.size(); ++t)
    if (red(diffuse[t]) && std::fabs(pos[t][2]) > 0.05f)
      ++n[pos[t][2] > 0.f ? 0 : 1];
  return n;
}

TEST(BrushSpace, InwardWoundSurfacesPaintAsOutwardOnes)
{
  // Seen from above, a stroke over the top of a sphere and on past its
  // silhouette: every space paints the same on the sphere wound either way.
  Camera above;
  above.position = {0.f, 0.f, 10.f};
  above.view_up = {0.f, 1.f, 0.f};
  for (const int space : {SPACE_OBJECT, SPACE_TANGENT, SPACE_SCREEN}) {
    std::array<std::size_t, 2> counts[2];
    bool left[2];
    for (const bool inwards : {false, true}) {
      SCOPED_TRACE(testing::Message() << "space " << space << (inwards ? " inwards" : " outwards"));
      const BaseMesh sphere = test::noisy_sphere(4, 0.f);
      PaintSurface surface(test::runtime(), inwards ? test::wound_inwards(sphere) : sphere, 3, AtlasStorage::Buffer);
      Stroke s = red_dab({0.f, 0.f, 1.f}, 0.3f, space);
      if (space == SPACE_SCREEN) {
        s.brush.camera = above;
        s.brush.has_camera = true;
      }
      for (int k = 1; k <= 12; ++k) {
        const double a = k * 15.0 * M_PI / 180.0;
        s.points.push_back({float(std::sin(a)), 0.f, float(std::cos(a))});
      }
      left[inwards] = surface.apply(s).left_surface;
      counts[inwards] = red_front_and_back(surface);
      EXPECT_GT(counts[inwards][0], 200u);
    }
    EXPECT_EQ(left[0], left[1]) << "space " << space;
    for (int side = 0; side < 2; ++side) // the same surface, in another atlas layout
      EXPECT_NEAR(double(counts[1][side]), double(counts[0][side]), 0.02 * double(counts[0][side]) + 2.0)
        << "space " << space << " side " << side;
  }
  // The tangent brush keeps to the side it started on, inside and outside.
  for (const bool inwards : {false, true}) {
    const BaseMesh sphere = test::noisy_sphere(4, 0.f);
    PaintSurface surface(test::runtime(), inwards ? test::wound_inwards(sphere) : sphere, 3, AtlasStorage::Buffer);
    surface.apply(red_dab({0.f, 0.f, 1.f}, 1.5f, SPACE_TANGENT));
    EXPECT_EQ(red_front_and_back(surface)[1], 0u) << (inwards ? "inwards" : "outwards");
  }
}

//! A roof: the plane z = 0 for y in [0, 4] (facing +z) and, from its edge
//! y = 4, a plane rising at 60 degrees (its normal 60 degrees from +z), both
//! 8 units wide in unit quads.
BaseMesh roof()
{
  std::vector<Vec3> pts;
  const double a = 60.0 * M_PI / 180.0;
  for (int v = 0; v <= 8; ++v)
    for (int x = 0; x <= 8; ++x)
      pts.push_back(v <= 4 ? Vec3{float(x), float(v), 0.f}
                           : Vec3{float(x), float(4 + (v - 4) * std::cos(a)), float((v - 4) * std::sin(a))});
  std::vector<std::vector<int>> faces;
  for (int v = 0; v < 8; ++v)
    for (int x = 0; x < 8; ++x)
      faces.push_back({v * 9 + x, v * 9 + x + 1, (v + 1) * 9 + x + 1, (v + 1) * 9 + x});
  return make_base_mesh(pts, faces, "roof");
}

TEST(BrushSpace, SprayDensityFallsWithTheCosineOfTheView)
{
  // Seen from straight above, a spray disc over the ridge: half of it on
  // the flat part, half on the part at 60 degrees, which has twice the area
  // under the same half disc. Each droplet adds the same displacement over
  // the same surface area, so the displacement per area is the density.
  PaintSurface surface(test::runtime(), roof(), 4, AtlasStorage::Buffer);
  Stroke s;
  s.points = {{4.f, 4.f, 0.f}};
  s.brush.radius = 1.5f;
  s.brush.falloff = FALLOFF_CONSTANT;
  s.brush.space = SPACE_SCREEN;
  s.brush.has_camera = true;
  s.brush.camera.position = {4.f, 4.f, 200.f};
  s.brush.camera.focal_point = {4.f, 4.f, 0.f};
  s.brush.camera.view_angle = 2.f;
  s.paint().op = PAINT_OP_ADD;
  s.paint().value[CHANNEL_DISPLACEMENT] = {1e-3f, 1e-3f, 1e-3f, 1.f};
  s.paint().alpha[CHANNEL_DISPLACEMENT] = 1.f;
  s.paint().spray_drops = 400;
  s.paint().spray_size = 0.08f;
  for (unsigned seed = 0; seed < 5; ++seed) {
    s.paint().spray_seed = seed;
    surface.apply(s);
  }
  const std::vector<Float4> pos = surface.atlas().read_limit_positions();
  const std::vector<Float4> material = surface.read_channels().material;
  // Texels lie evenly over both parts (unit quads): per part, the sum of the
  // displacement over the texels under the disc on the screen.
  double sum[2] = {0, 0};
  std::size_t under[2] = {0, 0};
  for (std::size_t t = 0; t < pos.size(); ++t) {
    const int part = pos[t][1] > 4.f + 1e-4f ? 1 : 0;
    sum[part] += material[t][1];
    if (std::hypot(pos[t][0] - 4.0, pos[t][1] - 4.0) <= s.brush.radius)
      ++under[part];
  }
  ASSERT_GT(sum[0], 0.0);
  const double ratio = (sum[1] / double(under[1])) / (sum[0] / double(under[0]));
  std::printf("spray density, 60-degree part / face-on part: %.3f (cos 60 = 0.5)\n", ratio);
  EXPECT_NEAR(ratio, 0.5, 0.15 * 0.5);
  // The same seed gives the same droplets.
  PaintSurface again(test::runtime(), roof(), 4, AtlasStorage::Buffer);
  for (unsigned seed = 0; seed < 5; ++seed) {
    s.paint().spray_seed = seed;
    again.apply(s);
  }
  const std::vector<Float4> repeat = again.read_channels().material;
  EXPECT_EQ(std::memcmp(repeat.data(), material.data(), material.size() * sizeof(Float4)), 0);
}

} // namespace
} // namespace meshpaint
