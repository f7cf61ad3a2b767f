// The brush pipeline and the paint equation.

#include "atlas/weld.h"
#include "core/errors.h"
#include "core/marks.h"
#include "paint/paint_surface.h"
#include "support/copies.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <algorithm> // for std::min
#include <array>     // for std::array
#include <cmath>   // for std::sqrt
#include <cstring> // for std::memcmp
#include <numeric> // for std::iota
#include <set>     // for std::set

namespace meshpaint {
namespace {

//! The message a stroke script is refused with, or "" when it is accepted.
std::string script_error(const std::string& json)
{
  try {
    parse_stroke_script(json);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

BaseMesh flat_square() { return test::flat_grid(6); }

//! A closed plate 4 x 4 x 0.1: top and bottom are near in space, far along the surface.
BaseMesh thin_plate()
{
  std::vector<Vec3> pts;
  for (float z : {0.f, 0.1f})
    for (int y = 0; y <= 4; ++y)
      for (int x = 0; x <= 4; ++x)
        pts.push_back({float(x), float(y), z});
  std::vector<std::vector<int>> faces;
  const auto v = [](int x, int y, int top) { return top * 25 + y * 5 + x; };
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      faces.push_back({v(x, y, 1), v(x + 1, y, 1), v(x + 1, y + 1, 1), v(x, y + 1, 1)});
      faces.push_back({v(x, y, 0), v(x, y + 1, 0), v(x + 1, y + 1, 0), v(x + 1, y, 0)});
    }
  for (int k = 0; k < 4; ++k) {
    faces.push_back({v(k, 0, 0), v(k + 1, 0, 0), v(k + 1, 0, 1), v(k, 0, 1)});
    faces.push_back({v(k + 1, 4, 0), v(k, 4, 0), v(k, 4, 1), v(k + 1, 4, 1)});
    faces.push_back({v(0, k + 1, 0), v(0, k, 0), v(0, k, 1), v(0, k + 1, 1)});
    faces.push_back({v(4, k, 0), v(4, k + 1, 0), v(4, k + 1, 1), v(4, k, 1)});
  }
  return make_base_mesh(pts, faces, "thin_plate");
}

Stroke dab_at(const Vec3& point, float radius, int falloff = FALLOFF_CONSTANT)
{
  Stroke s;
  s.points = {point};
  s.brush.radius = radius;
  s.brush.falloff = falloff;
  return s;
}

Stroke paint_diffuse(Stroke s, Float4 colour)
{
  s.paint().value[CHANNEL_DIFFUSE] = colour;
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  return s;
}

double distance(const Float4& a, const Vec3& b)
{
  return std::sqrt(double(a[0] - b[0]) * (a[0] - b[0]) + double(a[1] - b[1]) * (a[1] - b[1]) +
                   double(a[2] - b[2]) * (a[2] - b[2]));
}

TEST(Paint, CopyWithConstantFalloffPaintsExactlyTheDisc)
{
  PaintSurface surface(test::runtime(), flat_square(), 4, AtlasStorage::Buffer);
  const Vec3 centre{3.0f, 3.0f, 0.f};
  const float radius = 1.3f;
  const StrokeReport r = surface.apply(paint_diffuse(dab_at(centre, radius), {1.f, 0.f, 0.f, 1.f}));
  EXPECT_EQ(r.dabs_applied, 1u);
  const auto pos = surface.atlas().read_limit_positions();
  const auto ch = surface.read_channels();
  std::size_t inside = 0;
  for (std::size_t t = 0; t < pos.size(); ++t) {
    const bool in = distance(pos[t], centre) <= radius;
    inside += in;
    const Float4 expect = in ? Float4{1.f, 0.f, 0.f, 1.f} : Float4{0.8f, 0.8f, 0.8f, 1.f};
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(ch.diffuse[t][k], expect[k]) << "texel " << t << " at distance " << distance(pos[t], centre);
  }
  EXPECT_GT(inside, 100u);
}

TEST(Paint, BrushCentreSnapsToTheNearestTexelFromNearAndFar)
{
  // One culling pass finds the nearest texel wherever the point lies within
  // the radius; checked against every limit texel.
  PaintSurface surface(test::runtime(), test::noisy_sphere(8, 0.05f), 3, AtlasStorage::Buffer);
  const auto pos = surface.atlas().read_limit_positions();
  for (const float out : {0.f, 1e-4f, 0.05f, 0.4f, 1.5f}) {
    const Vec3 point{0.3f * (1.f + out), 0.5f * (1.f + out), 0.81f * (1.f + out)};
    double nearest = 1e30;
    for (const Float4& p : pos)
      nearest = std::min(nearest, distance(p, point));
    Vec3 centre;
    const auto patches = surface.brush_patches(point, 3.f, &centre);
    ASSERT_FALSE(patches.empty()) << "point moved out by " << out;
    double snapped = 1e30;
    for (const Float4& p : pos)
      if (p[0] == centre[0] && p[1] == centre[1] && p[2] == centre[2])
        snapped = distance(p, point);
    EXPECT_EQ(snapped, nearest) << "point moved out by " << out;
    // Beyond the radius nothing is reached.
    EXPECT_TRUE(surface.brush_patches(point, float(nearest) * 0.99f).empty()) << "point moved out by " << out;
  }
}

// A hint (the picker's patch and (u, v), or the last dab's texel) only
// starts the search lower: wherever it points, every dab gets the centre,
// normal, texel and patches it gets without one, ties to the lowest patch
// included (a grid corner is a texel of four patches).
TEST(Paint, AHintAnywhereSnapsAsWithoutOne)
{
  for (const AtlasStorage storage : test::storages())
    for (const bool grid : {false, true}) {
      const BaseMesh mesh = grid ? test::flat_grid(6) : test::noisy_sphere(8, 0.05f);
      PaintSurface hinted(test::runtime(), mesh, 3, storage), plain(test::runtime(), mesh, 3, storage);
      const int patches = hinted.atlas().layout(3).patches;
      const std::vector<Vec3> points =
        grid ? std::vector<Vec3>{{2.f, 3.f, 0.1f}, {3.f, 3.f, 0.f}, {2.5f, 2.f, -0.3f}, {0.f, 0.f, 0.5f}}
             : std::vector<Vec3>{{0.3f, 0.5f, 0.81f}, {0.f, 0.f, 1.2f}, {-0.7f, 0.1f, -0.6f}, {0.f, 1.f, 0.f}};
      for (const Vec3& point : points) {
        plain.hint_snap(-1, 0.0, 0.0);
        Vec3 c0, n0;
        CullRecord r0{};
        const std::vector<int> p0 = plain.brush_patches(point, 1.5f, &c0, &n0, 0.f, &r0);
        ASSERT_FALSE(p0.empty());
        const int tile = hinted.atlas().layout(3).tile, n = tile - 1;
        const double u0 = double(r0.closest_texel % tile) / n, v0 = double(r0.closest_texel / tile) / n;
        // The nearest texel itself, the same place in the last patch, a far
        // patch, and a corner of the first.
        const std::vector<std::array<double, 3>> hints = {
          {double(r0.patch), u0, v0}, {double(patches - 1), u0, v0}, {double(patches / 2), 0.5, 0.5}, {0.0, 1.0, 1.0}};
        for (const auto& h : hints) {
          hinted.hint_snap(int(h[0]), h[1], h[2]);
          Vec3 c1, n1;
          CullRecord r1{};
          EXPECT_EQ(hinted.brush_patches(point, 1.5f, &c1, &n1, 0.f, &r1), p0);
          EXPECT_EQ(std::memcmp(&c1, &c0, sizeof c0), 0);
          EXPECT_EQ(std::memcmp(&n1, &n0, sizeof n0), 0);
          EXPECT_EQ(r1.patch, r0.patch);
          EXPECT_EQ(r1.closest_texel, r0.closest_texel);
        }
      }
    }
}

// CPUs cull and reach by clusters of patches (brush_cull_clusters,
// brush_reach_clusters), GPUs patch by patch: the same centre, record and
// patches for brushes near and far, small and large, also where the
// coordinates are large beside the brush (a surface moved 10^4 away).
TEST(Paint, ClustersPlaceAsPatchesDo)
{
  for (const AtlasStorage storage : test::storages())
    for (const float offset : {0.f, 1e4f}) {
      BaseMesh mesh = test::noisy_sphere(8, 0.05f);
      for (Vec3& x : mesh.points)
        x = {x[0] + offset, x[1] - offset, x[2] + 0.5f * offset};
      PaintSurface clusters(test::runtime(), mesh, 3, storage), patches(test::runtime(), mesh, 3, storage);
      clusters.atlas().set_patch_items(true);
      patches.atlas().set_patch_items(false);
      for (const Vec3& at : std::vector<Vec3>{{0.3f, 0.5f, 0.81f}, {0.f, 0.f, 1.2f}, {-0.7f, 0.1f, -0.6f}, {3.f, 0.f, 0.f}})
        for (const float radius : {0.05f, 0.3f, 1.5f, 4.f}) {
          const Vec3 point{at[0] + offset, at[1] - offset, at[2] + 0.5f * offset};
          Vec3 c0, n0, c1, n1;
          CullRecord r0{}, r1{};
          const std::vector<int> p0 = patches.brush_patches(point, radius, &c0, &n0, 0.f, &r0);
          const std::vector<int> p1 = clusters.brush_patches(point, radius, &c1, &n1, 0.f, &r1);
          const std::string what = "offset " + std::to_string(offset) + ", radius " + std::to_string(radius);
          EXPECT_EQ(p1, p0) << what;
          EXPECT_EQ(std::memcmp(&c1, &c0, sizeof c0), 0) << what;
          EXPECT_EQ(std::memcmp(&n1, &n0, sizeof n0), 0) << what;
          EXPECT_EQ(r1.patch, r0.patch) << what;
          EXPECT_EQ(r1.closest_texel, r0.closest_texel) << what;
        }
    }
}

TEST(Paint, DoesNotBleedThroughTheAir)
{
  // The brush on the top of a plate 0.1 thick with radius 0.5 reaches the
  // bottom in space, but along the surface only across the rim, 2 away.
  PaintSurface surface(test::runtime(), thin_plate(), 4, AtlasStorage::Buffer);
  surface.apply(paint_diffuse(dab_at({2.f, 2.f, 0.1f}, 0.5f), {0.f, 0.f, 1.f, 1.f}));
  const auto pos = surface.atlas().read_limit_positions();
  const auto ch = surface.read_channels();
  std::size_t top = 0, bottom = 0;
  for (std::size_t t = 0; t < pos.size(); ++t) {
    const bool painted = ch.diffuse[t][2] == 1.f && ch.diffuse[t][0] == 0.f;
    if (painted && pos[t][2] > 0.05f)
      ++top;
    if (painted && pos[t][2] < 0.05f)
      ++bottom;
  }
  EXPECT_GT(top, 50u);
  EXPECT_EQ(bottom, 0u) << "paint reached the far side of the plate";
}

// The reached patches come in increasing order, by a sort of the few or a
// scan of the many (the flood's and the patch sets' lists).
TEST(Paint, MarkedItemsComeInOrderBySortOrByScan)
{
  const std::size_t n = 1000;
  for (const std::size_t every : {1, 3, 97}) { // scan, scan, sort
    std::vector<int> listed;
    Marks marks;
    marks.begin(n);
    for (std::size_t i = n; i-- > 0;)
      if ((i * 7919) % every == 0) { // a marked item every `every`, listed from the top
        listed.push_back(int(i));
        marks.mark(i);
      }
    std::vector<int> expected = listed;
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(marked_in_order(listed, marks, n), expected) << every;
    EXPECT_EQ(in_order(listed, n, [&marks](std::size_t i) { return marks.marked(i); }), expected) << every;
  }
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(in_order(all, n, [](std::size_t) { return true; }), all);
  EXPECT_TRUE(in_order({}, n, [](std::size_t) { return false; }).empty());
}

TEST(Paint, FalloffsShapeTheWeight)
{
  for (int falloff : {FALLOFF_LINEAR, FALLOFF_SMOOTHSTEP, FALLOFF_GAUSSIAN}) {
    PaintSurface surface(test::runtime(), flat_square(), 4, AtlasStorage::Buffer);
    Stroke s = dab_at({3.f, 3.f, 0.f}, 2.f, falloff);
    s.paint().value[CHANNEL_ROUGHNESS] = {1.f, 1.f, 1.f, 1.f};
    s.paint().alpha[CHANNEL_ROUGHNESS] = 1.f;
    surface.apply(s);
    const auto pos = surface.atlas().read_limit_positions();
    const auto ch = surface.read_channels();
    for (std::size_t t = 0; t < pos.size(); ++t) {
      const double u = distance(pos[t], {3.f, 3.f, 0.f}) / 2.0;
      if (u > 1)
        continue;
      const double w = falloff == FALLOFF_LINEAR ? 1 - u
                       : falloff == FALLOFF_SMOOTHSTEP ? 1 - u * u * (3 - 2 * u)
                                                       : std::exp(-4.5 * u * u);
      ASSERT_NEAR(ch.material[t][0], 0.5 + 0.5 * w, 1e-5) << "falloff " << falloff << " at " << u;
    }
  }
}

TEST(Paint, OpsOfThePaintEquation)
{
  struct Case
  {
    int op;
    float paint, coverage, expect; // surface roughness starts at 0.5
  };
  for (const Case c : {Case{PAINT_OP_COPY, 0.2f, 1.f, 0.2f}, Case{PAINT_OP_OVER, 1.0f, 0.25f, 0.625f},
                       Case{PAINT_OP_MAX, 0.2f, 1.f, 0.5f}, Case{PAINT_OP_MAX, 0.7f, 1.f, 0.7f},
                       Case{PAINT_OP_ADD, 0.25f, 1.f, 0.75f}, Case{PAINT_OP_SUBTRACT, 0.25f, 1.f, 0.25f}}) {
    PaintSurface surface(test::runtime(), flat_square(), 3, AtlasStorage::Buffer);
    Stroke s = dab_at({3.f, 3.f, 0.f}, 0.5f);
    s.paint().op = c.op;
    s.paint().value[CHANNEL_ROUGHNESS] = {c.paint, c.paint, c.paint, c.coverage};
    s.paint().alpha[CHANNEL_ROUGHNESS] = 1.f;
    surface.apply(s);
    const auto pos = surface.atlas().read_limit_positions();
    const auto ch = surface.read_channels();
    for (std::size_t t = 0; t < pos.size(); ++t)
      if (distance(pos[t], {3.f, 3.f, 0.f}) < 0.4)
        ASSERT_NEAR(ch.material[t][0], c.expect, 1e-6) << "op " << c.op << " paint " << c.paint;
  }
}

TEST(Paint, AlphaAndStrengthScaleTheBlend)
{
  PaintSurface surface(test::runtime(), flat_square(), 3, AtlasStorage::Buffer);
  Stroke s = paint_diffuse(dab_at({3.f, 3.f, 0.f}, 0.5f), {0.f, 0.f, 0.f, 1.f});
  s.paint().alpha[CHANNEL_DIFFUSE] = 0.5f;
  s.brush.strength = 0.5f;
  surface.apply(s);
  const auto pos = surface.atlas().read_limit_positions();
  const auto ch = surface.read_channels();
  for (std::size_t t = 0; t < pos.size(); ++t)
    if (distance(pos[t], {3.f, 3.f, 0.f}) < 0.4)
      ASSERT_NEAR(ch.diffuse[t][0], 0.8 * 0.75, 1e-6);
}

TEST(Paint, MaskProtectsAndLabelsAreSet)
{
  PaintSurface surface(test::runtime(), flat_square(), 4, AtlasStorage::Buffer);
  Stroke mask = dab_at({2.f, 3.f, 0.f}, 1.f);
  mask.paint().value[CHANNEL_MASK] = {1.f, 1.f, 1.f, 1.f};
  mask.paint().alpha[CHANNEL_MASK] = 1.f;
  surface.apply(mask);
  Stroke label = dab_at({3.f, 3.f, 0.f}, 1.5f);
  label.tool = Tool::Label;
  label.paint().value[CHANNEL_LABEL] = {7.f, 7.f, 7.f, 1.f};
  label.paint().alpha[CHANNEL_LABEL] = 1.f;
  surface.apply(label);
  const auto pos = surface.atlas().read_limit_positions();
  const auto ch = surface.read_channels();
  std::size_t labelled = 0;
  for (std::size_t t = 0; t < pos.size(); ++t) {
    const bool masked = distance(pos[t], {2.f, 3.f, 0.f}) <= 1.f;
    const bool brushed = distance(pos[t], {3.f, 3.f, 0.f}) <= 1.5f;
    ASSERT_EQ(ch.material[t][3], masked ? 1.f : 0.f);
    ASSERT_EQ(ch.material[t][2], brushed && !masked ? 7.f : 0.f) << "texel " << t;
    labelled += brushed && !masked;
  }
  EXPECT_GT(labelled, 50u);
}

TEST(Paint, WashCoversEverything)
{
  PaintSurface surface(test::runtime(), test::genus_two(), 3, AtlasStorage::Buffer);
  Stroke s = make_stroke(Tool::Wash);
  s.paint().value[CHANNEL_SPECULAR] = {0.25f, 0.5f, 0.75f, 1.f};
  s.paint().alpha[CHANNEL_SPECULAR] = 1.f;
  surface.apply(s);
  for (const Float4& v : surface.read_channels().specular)
    ASSERT_TRUE(v[0] == 0.25f && v[1] == 0.5f && v[2] == 0.75f);
}

TEST(Paint, AWashThroughAScreenPatternUsesItsCamera)
{
  // The pattern's coordinates are where each texel lands on the screen, so
  // the wash needs the view as a brush does.
  PaintSurface surface(test::runtime(), flat_square(), 3, AtlasStorage::Buffer);
  Stroke s = make_stroke(Tool::Wash);
  s.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  s.paint().pattern.kind = PATTERN_MARBLE;
  s.paint().pattern.coord = PATTERN_COORD_SCREEN;
  s.paint().pattern.transform = {8, 0, 0, 0, 0, 8, 0, 0, 0, 0, 8, 0};
  s.brush.has_camera = true;
  s.brush.camera.position = {3.f, 3.f, 10.f};
  s.brush.camera.focal_point = {3.f, 3.f, 0.f};
  surface.apply(s);
  float lo = 1.f, hi = 0.f;
  for (const Float4& v : surface.read_channels().diffuse) {
    lo = std::min(lo, v[1]);
    hi = std::max(hi, v[1]);
  }
  EXPECT_GT(hi - lo, 0.2f); // the marble's veins, not one colour
}

TEST(Paint, StrokeEndsWhereItLeavesTheSurface)
{
  PaintSurface surface(test::runtime(), flat_square(), 3, AtlasStorage::Buffer);
  Stroke s = paint_diffuse(dab_at({1.f, 1.f, 0.f}, 0.3f), {1.f, 1.f, 0.f, 1.f});
  s.points = {{1.f, 1.f, 0.f}, {1.f, 1.f, 5.f}}; // straight up, away from the plane
  const StrokeReport r = surface.apply(s);
  EXPECT_TRUE(r.left_surface);
  EXPECT_GE(r.dabs_applied, 1u);
  EXPECT_LT(r.dabs_applied, r.dabs + 1);
}

TEST(Paint, CopiesOfSharedTexelsStayIdentical)
{
  PaintSurface surface(test::runtime(), test::high_valence(), 4, AtlasStorage::Buffer);
  Stroke s = paint_diffuse(dab_at({0.f, 0.f, 1.0f}, 0.6f, FALLOFF_GAUSSIAN), {0.1f, 0.9f, 0.3f, 1.f});
  s.points = {{0.f, 0.f, 1.0f}, {0.5f, 0.5f, 0.3f}};
  surface.apply(s);
  EXPECT_EQ(test::differing_copies(surface.atlas().topology(), surface.atlas().layout(4),
                                    surface.read_channels().diffuse), 0u);
}

TEST(Paint, MirrorPaintsBothSides)
{
  PaintSurface surface(test::runtime(), flat_square(), 3, AtlasStorage::Buffer);
  Stroke s = paint_diffuse(dab_at({1.f, 3.f, 0.f}, 0.4f), {0.f, 1.f, 0.f, 1.f});
  s.brush.mirror_axis = 0; // the plane x = 3
  const StrokeReport r = surface.apply(s);
  EXPECT_EQ(r.dabs_applied, 2u);
  const PaintedSurface out = surface.painted_surface();
  bool left = false, right = false;
  for (std::size_t v = 0; v < out.diffuse.size(); ++v)
    if (out.diffuse[v][1] == 1.f) {
      left = left || out.surface.points[v][0] < 3.f;
      right = right || out.surface.points[v][0] > 3.f;
    }
  EXPECT_TRUE(left && right);
}

TEST(Paint, PatchLanesAndTexelItemsGiveTheSameBits)
{
  // CPU devices paint eight patches per work item (paint_patches), a patch
  // per lane, where the dab needs no brush normal and no raster: every op,
  // falloff and channel there, the mask's hold on the weight and the
  // label's locks, must leave the channels as paint_dab does.
  const auto strokes = [] {
    std::vector<Stroke> out;
    Stroke diffuse = paint_diffuse(dab_at({1.5f, 0.5f, 1.f}, 0.9f, FALLOFF_SMOOTHSTEP), {0.9f, 0.2f, 0.4f, 0.6f});
    diffuse.paint().op = PAINT_OP_OVER;
    diffuse.points.push_back({0.5f, 0.5f, 1.f});
    out.push_back(diffuse);
    Stroke mask = dab_at({0.5f, 0.5f, 1.f}, 0.5f, FALLOFF_LINEAR);
    mask.paint().value[CHANNEL_MASK] = {0.7f, 0.7f, 0.7f, 0.8f};
    mask.paint().alpha[CHANNEL_MASK] = 0.9f;
    out.push_back(mask);
    Stroke polish = dab_at({1.f, 0.5f, 1.f}, 0.8f, FALLOFF_GAUSSIAN);
    polish.paint().specular_coefficient = 0.3f;
    polish.paint().value[CHANNEL_SPECULAR] = {0.2f, 0.5f, 0.9f, 0.7f};
    polish.paint().alpha[CHANNEL_SPECULAR] = 0.8f;
    out.push_back(polish);
    Stroke hue = dab_at({1.5f, 0.2f, 1.f}, 0.7f, FALLOFF_LINEAR);
    hue.paint().op = PAINT_OP_MAX;
    hue.paint().value[CHANNEL_SPECULAR] = {0.6f, 0.1f, 0.3f, 1.f};
    hue.paint().alpha[CHANNEL_SPECULAR] = 1.f;
    hue.paint().value[CHANNEL_ROUGHNESS] = {0.8f, 0.f, 0.f, 0.5f};
    hue.paint().alpha[CHANNEL_ROUGHNESS] = 0.6f;
    out.push_back(hue);
    Stroke add = dab_at({0.8f, 0.8f, 1.f}, 1.1f, FALLOFF_CONSTANT);
    add.paint().op = PAINT_OP_ADD;
    add.brush.strength = 0.7f;
    add.paint().value[CHANNEL_DISPLACEMENT] = {0.05f, 0.f, 0.f, 1.f};
    add.paint().alpha[CHANNEL_DISPLACEMENT] = 1.f;
    add.paint().value[CHANNEL_DIFFUSE] = {0.3f, 0.3f, 0.3f, 1.f};
    add.paint().alpha[CHANNEL_DIFFUSE] = 0.5f;
    out.push_back(add);
    Stroke subtract = paint_diffuse(dab_at({1.2f, 0.6f, 1.f}, 0.6f, FALLOFF_SMOOTHSTEP), {0.1f, 0.4f, 0.2f, 1.f});
    subtract.paint().op = PAINT_OP_SUBTRACT;
    out.push_back(subtract);
    Stroke seven = dab_at({1.5f, 0.5f, 1.f}, 0.6f, FALLOFF_LINEAR);
    seven.tool = Tool::Label;
    seven.paint().value[CHANNEL_LABEL] = {7.f, 7.f, 7.f, 1.f};
    seven.paint().alpha[CHANNEL_LABEL] = 1.f;
    out.push_back(seven);
    Stroke locked = seven;
    locked.points = {{1.0f, 0.5f, 1.f}};
    locked.brush.radius = 1.2f;
    locked.paint().value[CHANNEL_LABEL] = {3.f, 3.f, 3.f, 1.f};
    locked.paint().locked_labels = {7};
    out.push_back(locked);
    Stroke merge = seven;
    merge.brush.radius = 1.5f;
    merge.paint().value[CHANNEL_LABEL] = {5.f, 5.f, 5.f, 1.f};
    merge.paint().only_over_label = 3;
    out.push_back(merge);
    Stroke copy = paint_diffuse(dab_at({0.5f, 0.8f, 1.f}, 0.7f, FALLOFF_SMOOTHSTEP), {0.f, 0.8f, 0.1f, 1.f});
    copy.paint().op = PAINT_OP_COPY;
    copy.brush.strength = 0.6f;
    out.push_back(copy);
    return out;
  }();
  std::vector<PaintChannels> results;
  for (const bool per_patch : {true, false}) {
    PaintSurface surface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer);
    surface.atlas().set_patch_items(per_patch);
    for (const Stroke& s : strokes)
      ASSERT_GT(surface.apply(s).dabs_applied, 0u);
    results.push_back(surface.read_channels());
  }
  const auto same = [](const std::vector<Float4>& a, const std::vector<Float4>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Float4)) == 0;
  };
  EXPECT_TRUE(same(results[0].diffuse, results[1].diffuse));
  EXPECT_TRUE(same(results[0].specular, results[1].specular));
  EXPECT_TRUE(same(results[0].material, results[1].material));
  const PaintChannels untouched =
    PaintSurface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer).read_channels();
  EXPECT_FALSE(same(results[0].diffuse, untouched.diffuse));
  EXPECT_FALSE(same(results[0].specular, untouched.specular));
  EXPECT_FALSE(same(results[0].material, untouched.material));
  std::set<float> labels;
  for (const Float4& m : results[0].material)
    labels.insert(m[2]);
  EXPECT_EQ(labels, (std::set<float>{0.f, 3.f, 5.f, 7.f})) << "the locked 7 kept, the 3s merged in part";
}

TEST(StrokeScript, SamplesFollowSpacingAndPressure)
{
  Stroke s = dab_at({0.f, 0.f, 0.f}, 1.f);
  s.points = {{0.f, 0.f, 0.f}, {2.f, 0.f, 0.f}};
  s.brush.spacing = 0.5f;
  const auto samples = stroke_samples(s);
  ASSERT_EQ(samples.size(), 5u);
  for (std::size_t k = 0; k < samples.size(); ++k)
    EXPECT_NEAR(samples[k].centre[0], 0.5 * k, 1e-6);
  s.pressure = {0.5f, 0.5f};
  EXPECT_EQ(stroke_samples(s).size(), 9u);
}

TEST(StrokeScript, ErrorsNameTheStrokeAndKey)
{
  const auto message = script_error;
  const std::string ok = R"({"tool": "paint", "points": [[0,0,0]], "radius": 1, "channels": {"diffuse": [1,0,0]}})";
  EXPECT_EQ(parse_stroke_script("{\"strokes\": [" + ok + "]}").strokes.size(), 1u);
  EXPECT_EQ(message("{\"strokes\": [" + ok + ", {\"tool\": \"paint\", \"radius\": -1}]}"),
            "stroke 1: \"points\" is required: the path of the stroke as [[x, y, z], ...]");
  EXPECT_EQ(message(R"({"strokes": [{"tool": "paint", "points": [[0,0,0]], "radius": -2, "channels": {"roughness": 1}}]})"),
            "stroke 0: \"radius\" must be a number from 1e-30 to 1e+30");
  EXPECT_EQ(message(R"({"strokes": [{"tool": "paint", "points": [[0,0,0]], "radius": 1, "strength": "lots", "channels": {"roughness": 1}}]})"),
            "stroke 0: \"strength\" must be a number from 0 to 1");
  EXPECT_EQ(message(R"({"strokes": [{"tool": "spray"}]})"), "stroke 0: \"tool\" must be one of paint, label, wash, dip, smooth, blur, sculpt, inflate, flatten, smear, grab, fill, merge");
  EXPECT_EQ(message(R"({"strokes": [{"tool": "paint", "points": [[0,0,0]], "radius": 1, "edit_level": 2, "channels": {"roughness": 1}}]})"),
            "stroke 0: \"edit_level\" has no meaning for a paint stroke, which does not move the surface");
  EXPECT_EQ(message(R"({"strokes": [{"tool": "grab", "points": [[0,0,0]], "radius": 1, "mirror": "x"}]})"),
            "stroke 0: \"mirror\" has no meaning for a grab stroke, which pulls one region");
  EXPECT_EQ(message(R"({"strokes": [{"tool": "sculpt", "points": [[0,0,0]], "radius": 1, "amount": 1, "edit_level": 0}]})"),
            "stroke 0: \"edit_level\" must be an integer from 1 to 12");
  EXPECT_EQ(message(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "space": "screen", "channels": {"roughness": 1}}]})"),
            "stroke 0: \"camera\" is required for a screen-space brush or pattern: the view it is drawn in");
  EXPECT_EQ(message(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "space": "screen", "channels": {"roughness": 1},
      "camera": {"position": [0,0,1], "focal_point": [0,0,1], "view_up": [0,1,0]}}]})"),
            "stroke 0: \"camera\" \"focal_point\" must differ from \"position\"");
  EXPECT_EQ(message(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "backfaces": "paint", "channels": {"roughness": 1}}]})"),
            "stroke 0: \"backfaces\" has no meaning unless \"space\" is \"screen\" or \"tangent\"");
  EXPECT_EQ(message(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "space": "tangent", "spray": {"drops": 3, "size": 1},
      "channels": {"roughness": 1}}]})"),
            "stroke 0: \"spray\" has no meaning unless a paint or label stroke is in screen space");
  EXPECT_EQ(message(R"({"strokes": [{"colour": [1,0,0]}]})").substr(0, 40), "stroke 0: \"colour\" is not a stroke key (");
  EXPECT_EQ(message(R"({"strokes": [{"points": [[0,0]], "radius": 1}]})"), "stroke 0: \"points\" must be a list of [x, y, z] points");
  EXPECT_EQ(message(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "channels": {"gloss": 1}}]})").substr(0, 51),
            "stroke 0: \"channels\" has an unknown channel \"gloss\"");
  EXPECT_EQ(message(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "channels": {"diffuse": [1,0,0]}, "falloff": "cubic"}]})"),
            "stroke 0: \"falloff\" must be one of constant, linear, smoothstep, gaussian");
  EXPECT_EQ(message("{\"strokes\": [" + ok + "], \"lvl\": 3}"), "stroke script: \"lvl\" is not a script key (level, strokes)");
  EXPECT_EQ(message("{\"strokes\": [").substr(0, 40), "stroke script is not valid JSON: parse e");
  EXPECT_EQ(message(R"({"strokes": [{"tool": "label", "points": [[0,0,0]], "radius": 1, "channels": {"label": 2.5}}]})"),
            "stroke 0: \"channels\" \"label\" must be an integer class id from 0 to 16777216");
}

} // namespace
} // namespace meshpaint

namespace meshpaint {
namespace {

bool same_bits(const PaintChannels& a, const PaintChannels& b)
{
  const auto eq = [](const std::vector<Float4>& x, const std::vector<Float4>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(Float4)) == 0;
  };
  return eq(a.diffuse, b.diffuse) && eq(a.specular, b.specular) && eq(a.material, b.material);
}

TEST(Undo, UndoingEverythingGivesBackTheChannelsBitForBit)
{
  PaintSurface surface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer);
  const PaintChannels start = surface.read_channels();
  std::vector<PaintChannels> after;
  unsigned seed = 12345;
  const auto next = [&seed] { return (seed = seed * 1103515245u + 12345u) / 65536 % 1000 / 1000.f; };
  for (int k = 0; k < 8; ++k) {
    Stroke s;
    s.points = {{5 * next(), 3 * next(), next()}, {5 * next(), 3 * next(), next()}};
    s.brush.radius = 0.3f + next();
    s.brush.falloff = k % 4;
    s.paint().op = k % 5;
    s.paint().value[k % CHANNEL_COUNT] = {next(), next(), next(), 1.f};
    s.paint().alpha[k % CHANNEL_COUNT] = 0.5f + 0.5f * next();
    if (k % CHANNEL_COUNT == CHANNEL_LABEL)
      s.tool = Tool::Label, s.paint().value[CHANNEL_LABEL] = {3.f, 3.f, 3.f, 1.f};
    surface.apply(s);
    after.push_back(surface.read_channels());
  }
  EXPECT_FALSE(same_bits(after.back(), start));
  const std::size_t depth = surface.undo_log().undo_depth();
  EXPECT_GE(depth, 6u);
  for (std::size_t k = depth; k-- > 0;) {
    ASSERT_TRUE(surface.undo());
    if (depth == after.size()) // every stroke touched the surface: each undo gives back the state before it
      EXPECT_TRUE(same_bits(surface.read_channels(), k == 0 ? start : after[k - 1])) << "after undoing stroke " << k;
  }
  EXPECT_FALSE(surface.undo());
  EXPECT_TRUE(same_bits(surface.read_channels(), start));
  while (surface.redo()) {
  }
  EXPECT_TRUE(same_bits(surface.read_channels(), after.back()));
}

TEST(Undo, BudgetForgetsTheOldestStrokesAndSaysSo)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, AtlasStorage::Buffer);
  Stroke s = dab_at({3.f, 3.f, 0.f}, 1.f);
  s.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  surface.apply(s);
  const std::size_t one = surface.undo_log().bytes();
  surface.undo_log().set_budget(2 * one + one / 2);
  for (int k = 0; k < 4; ++k)
    surface.apply(s);
  EXPECT_EQ(surface.undo_log().undo_depth(), 2u);
  const auto notes = surface.undo_log().take_messages();
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes.front().find("forgot the"), std::string::npos) << notes.front();
  // A new stroke after undo forgets what could be redone.
  EXPECT_TRUE(surface.undo());
  EXPECT_TRUE(surface.undo_log().can_redo());
  surface.apply(s);
  EXPECT_FALSE(surface.undo_log().can_redo());
}

} // namespace
} // namespace meshpaint

namespace meshpaint {
namespace {

std::vector<std::size_t> texels_near(PaintSurface& surface, const Vec3& c, double r)
{
  const auto pos = surface.atlas().read_limit_positions();
  std::vector<std::size_t> out;
  for (std::size_t t = 0; t < pos.size(); ++t)
    if (distance(pos[t], c) < r)
      out.push_back(t);
  return out;
}

TEST(PaintModes, RemoverPaintsTheUnderlyingMaterialBack)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 3, AtlasStorage::Buffer);
  Stroke red = paint_diffuse(dab_at({3.f, 3.f, 0.f}, 1.f), {1.f, 0.f, 0.f, 1.f});
  red.paint().value[CHANNEL_ROUGHNESS] = {0.9f, 0.9f, 0.9f, 1.f};
  red.paint().alpha[CHANNEL_ROUGHNESS] = 1.f;
  surface.apply(red);
  const Stroke remover = parse_stroke_script(
    R"({"strokes": [{"points": [[3, 3, 0]], "radius": 1.5, "falloff": "constant", "mode": "remover"}]})").strokes[0];
  surface.apply(remover);
  const auto ch = surface.read_channels();
  for (const std::size_t t : texels_near(surface, {3.f, 3.f, 0.f}, 1.4)) {
    ASSERT_EQ(ch.diffuse[t][0], 0.8f);
    ASSERT_EQ(ch.diffuse[t][1], 0.8f);
    ASSERT_EQ(ch.material[t][0], 0.5f);
  }
}

TEST(PaintModes, PolishAndSandpaperChangeShineNotColour)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 3, AtlasStorage::Buffer);
  Stroke tint = dab_at({3.f, 3.f, 0.f}, 1.f);
  tint.paint().value[CHANNEL_SPECULAR] = {0.2f, 0.1f, 0.05f, 1.f};
  tint.paint().alpha[CHANNEL_SPECULAR] = 1.f;
  surface.apply(tint);
  surface.apply(parse_stroke_script(R"({"strokes": [{"points": [[3, 3, 0]], "radius": 1, "falloff": "constant",
                                       "mode": "polish", "coefficient": 0.8}]})").strokes[0]);
  auto ch = surface.read_channels();
  const auto inside = texels_near(surface, {3.f, 3.f, 0.f}, 0.9);
  for (const std::size_t t : inside) {
    ASSERT_NEAR(ch.specular[t][0], 0.8f, 1e-6);
    ASSERT_NEAR(ch.specular[t][1], 0.4f, 1e-6);
    ASSERT_NEAR(ch.specular[t][2], 0.2f, 1e-6);
    ASSERT_NEAR(ch.material[t][0], 0.1f, 1e-6);
    ASSERT_EQ(ch.diffuse[t][0], 0.8f);
  }
  surface.apply(parse_stroke_script(R"({"strokes": [{"points": [[3, 3, 0]], "radius": 1, "falloff": "constant",
                                       "mode": "sandpaper"}]})").strokes[0]);
  ch = surface.read_channels();
  for (const std::size_t t : inside) {
    ASSERT_NEAR(ch.material[t][0], 0.9f, 1e-6);
    ASSERT_NEAR(ch.specular[t][0], 0.05f, 1e-6);
    ASSERT_NEAR(ch.specular[t][2], 0.0125f, 1e-6);
  }
}

TEST(PaintModes, DyeAndMaterialCheckTheirChannels)
{
  const auto fails = script_error;
  EXPECT_NE(fails(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "mode": "dye", "channels": {"roughness": 0.2}}]})"), "");
  EXPECT_NE(fails(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "mode": "material", "channels": {"diffuse": [1,0,0]}}]})"), "");
  EXPECT_EQ(fails(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "mode": "material",
                       "channels": {"diffuse": [1,0,0], "specular": [1,1,1], "roughness": 0.3}}]})"), "");
}

TEST(PatternPaint, SolidTexturesVaryAndFollowTheirTransform)
{
  std::vector<std::vector<Float4>> results;
  for (const char* transform : {"[[1,0,0,0],[0,1,0,0],[0,0,1,0]]", "[[0,1,0,0.37],[1,0,0,0],[0,0,1,0.11]]"}) {
    PaintSurface surface(test::runtime(), test::genus_two(), 3, AtlasStorage::Buffer);
    surface.apply(parse_stroke_script(std::string(R"({"strokes": [{"tool": "wash", "channels": {"diffuse": [1, 0, 0]},
      "pattern": {"type": "marble", "scale": 2, "transform": )") + transform + "}}]}").strokes[0]);
    results.push_back(surface.read_channels().diffuse);
    double lo = 1, hi = 0;
    for (const Float4& d : results.back()) {
      const double t = 1.0 - d[1] / 0.8; // green falls from 0.8 to 0 as the pattern goes to 1
      ASSERT_GE(t, -1e-6);
      ASSERT_LE(t, 1 + 1e-6);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    EXPECT_GT(hi - lo, 0.5) << "a marble wash should show veins";
  }
  EXPECT_NE(std::memcmp(results[0].data(), results[1].data(), results[0].size() * sizeof(Float4)), 0);
}

TEST(PatternPaint, DipPaintsBelowTheBathLevelOnly)
{
  PaintSurface surface(test::runtime(), test::genus_two(), 3, AtlasStorage::Buffer);
  surface.apply(parse_stroke_script(R"({"strokes": [{"tool": "dip", "channels": {"diffuse": [0, 0, 1]},
    "pattern": {"type": "bath", "scale": 20, "transform": [[1,0,0,0],[0,1,0,0],[0,0,1,-0.5]]}}]})").strokes[0]);
  const auto pos = surface.atlas().read_limit_positions();
  const auto ch = surface.read_channels();
  std::size_t below = 0, above = 0;
  for (std::size_t t = 0; t < pos.size(); ++t) {
    if (pos[t][2] < 0.4f) {
      ASSERT_EQ(ch.diffuse[t][2], 1.f);
      ++below;
    } else if (pos[t][2] > 0.6f) {
      ASSERT_EQ(ch.diffuse[t][2], 0.8f);
      ++above;
    }
  }
  EXPECT_GT(below, 100u);
  EXPECT_GT(above, 100u);
}

TEST(StrokeScript, RubberbandAndRubberstamp)
{
  const std::string path = R"("points": [[0,0,0], [5,5,0], [2,0,0]], "radius": 1, "spacing": 0.5, "channels": {"diffuse": [1,0,0]})";
  const Stroke band = parse_stroke_script(R"({"strokes": [{"stroke": "rubberband", )" + path + "}]}").strokes[0];
  ASSERT_EQ(band.points.size(), 2u);
  EXPECT_EQ(stroke_samples(band).size(), 5u); // 0, 0.5, ... 2 along the straight line
  const Stroke stamp = parse_stroke_script(R"({"strokes": [{"stroke": "rubberstamp", )" + path + "}]}").strokes[0];
  EXPECT_EQ(stroke_samples(stamp).size(), 1u);
}

} // namespace
} // namespace meshpaint

namespace meshpaint {
namespace {

TEST(PatternPaint, ImagesInPatchParametersAndVolumesInSpace)
{
  {
    PaintSurface surface(test::runtime(), test::flat_grid(2), 3, AtlasStorage::Buffer);
    Stroke s = parse_stroke_script(R"({"strokes": [{"tool": "wash", "channels": {"diffuse": [1, 0, 0]},
      "pattern": {"type": "image", "coord": "uv", "file": "halves.png"}}]})").strokes[0];
    auto image = std::make_shared<Raster>();
    image->width = 2;
    image->height = 1;
    image->samples = {0.f, 1.f}; // left half clear, right half full
    s.paint().pattern.raster = image;
    surface.apply(s);
    const auto ch = surface.read_channels();
    const LevelLayout l = surface.atlas().layout(3);
    for (int p = 0; p < l.patches; ++p)
      for (int j = 0; j <= l.n; ++j) {
        ASSERT_EQ(ch.diffuse[l.index(p, 1, j)][1], 0.8f) << "u = 1/4 lies on the clear pixel's centre";
        ASSERT_EQ(ch.diffuse[l.index(p, 3, j)][1], 0.f) << "u = 3/4 lies on the full pixel's centre";
      }
  }
  {
    PaintSurface surface(test::runtime(), test::genus_two(), 3, AtlasStorage::Buffer);
    Stroke s = parse_stroke_script(R"({"strokes": [{"tool": "dip", "channels": {"diffuse": [0, 1, 0]},
      "pattern": {"type": "volume", "file": "layers.vti"}}]})").strokes[0];
    auto volume = std::make_shared<Raster>();
    volume->width = volume->height = volume->depth = 2;
    volume->samples = {0, 0, 0, 0, 1, 1, 1, 1}; // z = 0 layer empty, z = 1 layer full
    s.paint().pattern.raster = volume;
    surface.apply(s);
    const auto pos = surface.atlas().read_limit_positions();
    const auto ch = surface.read_channels();
    for (std::size_t t = 0; t < pos.size(); ++t) {
      if (pos[t][2] < 0.2f)
        ASSERT_EQ(ch.diffuse[t][1], 0.8f);
      if (pos[t][2] > 0.8f)
        ASSERT_EQ(ch.diffuse[t][1], 1.f);
    }
  }
}

TEST(PatternPaint, MissingSamplesAreAnError)
{
  PaintSurface surface(test::runtime(), test::flat_grid(2), 2, AtlasStorage::Buffer);
  const Stroke s = parse_stroke_script(R"({"strokes": [{"tool": "wash", "channels": {"diffuse": [1, 0, 0]},
      "pattern": {"type": "image", "file": "nowhere.png"}}]})").strokes[0];
  EXPECT_THROW(surface.apply(s), InputError);
}

TEST(Paint, BrushImageShapesTheDab)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, AtlasStorage::Buffer);
  Stroke s = paint_diffuse(dab_at({3.f, 3.f, 0.f}, 1.5f), {0.f, 0.f, 1.f, 1.f});
  s.points = {{3.f, 3.f, 0.f}, {3.5f, 3.f, 0.f}}; // heading +x: the stamp's u axis
  s.brush.spacing = 10.f;                                // one dab only
  auto stamp = std::make_shared<Raster>();
  stamp->width = 2;
  stamp->height = 1;
  stamp->samples = {0.f, 1.f}; // nothing behind the centre, everything ahead
  s.brush.stamp = stamp;
  s.brush.stamp_file = "half.png";
  surface.apply(s);
  const auto pos = surface.atlas().read_limit_positions();
  const auto ch = surface.read_channels();
  std::size_t ahead = 0;
  for (std::size_t t = 0; t < pos.size(); ++t) {
    if (distance(pos[t], {3.f, 3.f, 0.f}) > 1.4)
      continue;
    // Pixel centres at u = 1/4 and 3/4 of the diameter: clear before x = 2.25,
    // full after x = 3.75, blended between.
    if (pos[t][0] < 2.2f)
      ASSERT_EQ(ch.diffuse[t][2], 0.8f) << "behind the centre the stamp is empty";
    if (pos[t][0] > 3.8f) {
      ASSERT_EQ(ch.diffuse[t][2], 1.f);
      ++ahead;
    }
  }
  EXPECT_GT(ahead, 20u);
}

} // namespace
} // namespace meshpaint

namespace meshpaint {
namespace {

TEST(Paint, SmearDragsColourAlongTheStroke)
{
  PaintSurface surface(test::runtime(), test::flat_grid(8), 4, AtlasStorage::Buffer);
  surface.apply(paint_diffuse(dab_at({2.f, 4.f, 0.f}, 0.8f), {0.f, 0.f, 1.f, 1.f})); // a blue spot
  const auto before = surface.read_channels();
  const Stroke smear = parse_stroke_script(R"({"strokes": [{"tool": "smear", "points": [[2, 4, 0], [6, 4, 0]],
                                              "radius": 0.6, "falloff": "constant", "spacing": 0.5, "strength": 0.5}]})")
                         .strokes[0];
  surface.apply(smear);
  const auto pos = surface.atlas().read_limit_positions();
  const auto after = surface.read_channels();
  // Blue now reaches well past the spot, fading along the way.
  double blue_at_4 = 0, blue_at_5_5 = 0;
  for (std::size_t t = 0; t < pos.size(); ++t) {
    if (distance(pos[t], {4.f, 4.f, 0.f}) < 0.2)
      blue_at_4 = std::max(blue_at_4, double(after.diffuse[t][2] - after.diffuse[t][0]));
    if (distance(pos[t], {5.5f, 4.f, 0.f}) < 0.2)
      blue_at_5_5 = std::max(blue_at_5_5, double(after.diffuse[t][2] - after.diffuse[t][0]));
    if (distance(pos[t], {4.f, 4.f, 0.f}) < 0.2)
      ASSERT_EQ(before.diffuse[t][2], 0.8f) << "was not blue before";
  }
  EXPECT_GT(blue_at_4, 0.05);
  EXPECT_GT(blue_at_4, blue_at_5_5);
  // Off the path nothing changed.
  for (std::size_t t = 0; t < pos.size(); ++t)
    if (std::fabs(pos[t][1] - 4.f) > 1.f)
      ASSERT_EQ(after.diffuse[t][2], before.diffuse[t][2]);
}

} // namespace
} // namespace meshpaint

namespace meshpaint {
namespace {

TEST(StrokeScript, BlurAndSmearOps)
{
  const auto script = parse_stroke_script(R"({"strokes": [
    {"points": [[0,0,0]], "radius": 1, "op": "blur", "iterations": 2},
    {"points": [[0,0,0], [1,0,0]], "radius": 1, "op": "smear"}]})");
  EXPECT_EQ(script.strokes[0].tool, Tool::Blur);
  EXPECT_TRUE(script.strokes[0].smooth().target_colour);
  EXPECT_EQ(script.strokes[1].tool, Tool::Smear);
  EXPECT_THROW(parse_stroke_script(R"({"strokes": [{"points": [[0,0,0]], "radius": 1, "op": "blur",
                                      "channels": {"diffuse": [1,0,0]}}]})"),
               InputError);
}

} // namespace
} // namespace meshpaint

namespace meshpaint {
namespace {

TEST(StrokeScript, RefusesStrokesOfAbsurdLengthAndTaubinColours)
{
  const auto fails = script_error;
  EXPECT_NE(fails(R"({"strokes": [{"points": [[0,0,0], [1000,0,0]], "radius": 1e-9,
                     "channels": {"diffuse": [1,0,0]}}]})").find("too small for the path"), std::string::npos);
  EXPECT_NE(fails(R"({"strokes": [{"tool": "blur", "points": [[0,0,0]], "radius": 1, "method": "taubin"}]})")
              .find("taubin is for positions"), std::string::npos);
}

} // namespace
} // namespace meshpaint
