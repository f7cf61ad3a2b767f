// Multiresolution editing: details S - up(down(S)) in local frames, edits at
// a coarse level that carry the fine detail along, and the grab tool.

#include "atlas/multires.h"
#include "core/errors.h"
#include "paint/paint_surface.h"
#include "support/copies.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <algorithm> // for std::sort
#include <array>   // for std::array
#include <cmath>   // for std::sqrt, std::sin, std::cos, std::isnan
#include <cstdio>  // for std::printf
#include <cstring> // for std::memcmp
#include <limits>  // for std::numeric_limits
#include <numeric> // for std::iota

namespace meshpaint {
namespace {

constexpr int kLevel = 5;

double length_of(const Vec3& v) { return std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]); }

double distance(const Float4& a, const Float4& b)
{
  return std::sqrt(double(a[0] - b[0]) * (a[0] - b[0]) + double(a[1] - b[1]) * (a[1] - b[1]) +
                   double(a[2] - b[2]) * (a[2] - b[2]));
}

//! Fine bumps along the radius, a function of the position so that every
//! stored copy of a texel moves alike.
void add_bumps(std::vector<Float4>& texels, float height)
{
  for (Float4& t : texels) {
    const double r = std::sqrt(double(t[0]) * t[0] + double(t[1]) * t[1] + double(t[2]) * t[2]);
    if (r == 0) // no radius to bump along (a grid through the origin)
      continue;
    const double h = height * std::sin(48.0 * t[0]) * std::sin(48.0 * t[1]) * std::sin(48.0 * t[2]);
    for (int k = 0; k < 3; ++k)
      t[k] = float(t[k] * (1.0 + h / r));
  }
}

std::vector<int> every_patch(const Atlas& atlas)
{
  std::vector<int> all(std::size_t(atlas.topology().patch_count));
  std::iota(all.begin(), all.end(), 0);
  return all;
}

bool same_bits(const std::vector<Float4>& a, const std::vector<Float4>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Float4)) == 0;
}

//! A bumpy sphere at level 5 in an atlas of its own.
struct BumpyAtlas
{
  Atlas atlas{test::runtime(), test::noisy_sphere(3, 0.f), kLevel, AtlasStorage::Buffer};
  std::vector<Float4> fine;
  double diagonal = atlas.base_mesh().diagonal();

  BumpyAtlas()
  {
    atlas.subdivide(1, kLevel);
    fine = atlas.read_positions(kLevel);
    add_bumps(fine, 0.02f);
    atlas.write_positions(kLevel, fine);
    atlas.compute_limit();
  }
};

TEST(Multires, WithoutAnEditReconstructionGivesTheFineSurfaceBack)
{
  for (const int edit : {1, 2, 3}) {
    BumpyAtlas b;
    Multires multires(b.atlas);
    multires.encode(edit);
    EXPECT_TRUE(same_bits(b.atlas.read_positions(kLevel), b.fine)) << "encoding changed the finest level";
    multires.reconstruct(every_patch(b.atlas));
    const std::vector<Float4> back = b.atlas.read_positions(kLevel);
    double worst = 0;
    for (std::size_t t = 0; t < back.size(); ++t)
      worst = std::max(worst, distance(back[t], b.fine[t]));
    EXPECT_LT(worst, 1e-5 * b.diagonal) << "edit level " << edit;
    EXPECT_EQ(test::differing_copies(b.atlas.topology(), b.atlas.layout(kLevel), back), 0u);
  }
}

TEST(Multires, DetailsFollowARigidMotionOfTheBase)
{
  BumpyAtlas b;
  Multires multires(b.atlas);
  multires.encode(2);
  // 40 degrees about (1, 2, 3), then a shift.
  const double angle = 40.0 * M_PI / 180.0, n = std::sqrt(14.0);
  const double x = 1 / n, y = 2 / n, z = 3 / n, c = std::cos(angle), s = std::sin(angle);
  const double r[3][3] = {{c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s},
                          {y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s},
                          {z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)}};
  const double shift[3] = {0.5, -1.25, 2.0};
  const auto move = [&](const Float4& p) {
    Float4 q = p;
    for (int i = 0; i < 3; ++i)
      q[i] = float(r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + shift[i]);
    return q;
  };
  std::vector<Float4> base = b.atlas.read_positions(2);
  for (Float4& p : base)
    p = move(p);
  b.atlas.write_positions(2, base);
  multires.reconstruct(every_patch(b.atlas));
  const std::vector<Float4> moved = b.atlas.read_positions(kLevel);
  double worst = 0;
  for (std::size_t t = 0; t < moved.size(); ++t)
    worst = std::max(worst, distance(moved[t], move(b.fine[t])));
  EXPECT_LT(worst, 1e-4 * b.diagonal);
}

//! An edit of the base at `edit_level` near one point, rebuilt on the
//! reach of the patches it moved, against everything rebuilt.
void expect_reach_enough(int edit_level)
{
  SCOPED_TRACE("edit level " + std::to_string(edit_level));
  BumpyAtlas b;
  Multires multires(b.atlas);
  multires.encode(edit_level);
  // Move the base near one point, smoothly, the same for every copy.
  std::vector<Float4> base = b.atlas.read_positions(edit_level);
  const Float4 at = base[base.size() / 3];
  for (Float4& p : base) {
    const double d = distance(p, at);
    if (d < 0.5)
      for (int k = 0; k < 3; ++k)
        p[k] += float(0.2 * (1 - d / 0.5) * (k == 2 ? 1.0 : 0.3));
  }
  b.atlas.write_positions(edit_level, base);
  // Every patch holding a copy of a moved point, as a brush's patches are.
  std::vector<int> moved;
  const LevelLayout le = b.atlas.layout(edit_level);
  for (int p = 0; p < le.patches; ++p)
    for (int t = 0; t < le.tile * le.tile; ++t)
      if (distance(base[le.index(p, 0, 0) + std::size_t(t)], at) < 0.6) {
        moved.push_back(p);
        break;
      }
  multires.reconstruct(multires.reach(moved));
  const std::vector<Float4> local = b.atlas.read_positions(kLevel);
  multires.reconstruct(every_patch(b.atlas));
  const std::vector<Float4> global = b.atlas.read_positions(kLevel);
  double worst = 0;
  for (std::size_t t = 0; t < local.size(); ++t)
    worst = std::max(worst, distance(local[t], global[t]));
  EXPECT_LT(worst, 1e-6 * b.diagonal);
  EXPECT_FALSE(same_bits(local, b.fine));
  EXPECT_EQ(test::differing_copies(b.atlas.topology(), b.atlas.layout(kLevel), local), 0u);
}

TEST(Multires, RebuildingTheReachEqualsRebuildingEverything)
{
  for (int level = 1; level <= 3; ++level)
    expect_reach_enough(level);
}

Stroke coarse_inflate(const Vec3& centre, float radius, float amount, int edit_level)
{
  Stroke s = make_stroke(Tool::Inflate);
  s.points = {centre};
  s.brush.radius = radius;
  s.brush.falloff = FALLOFF_SMOOTHSTEP;
  s.move().amount = amount;
  s.set_edit_level(edit_level);
  return s;
}

//! Heights of the fine detail per finest texel: the normal coordinate of
//! the details over `level`, less its mean over the patch (which holds the
//! slow part that changes with the curvature of the base); on texels strictly
//! inside tiles only (a side's or corner's copies hold details in one patch
//! alone), NaN elsewhere.
std::vector<double> bump_heights(Atlas& atlas, int level)
{
  Multires probe(atlas);
  probe.encode(level);
  const std::vector<Float4> details = probe.read_details();
  const LevelLayout l = atlas.layout(atlas.max_level());
  const std::size_t tile = std::size_t(l.tile);
  std::vector<double> h(details.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t p = 0; p < std::size_t(l.patches); ++p) {
    const auto at = [&](std::size_t i, std::size_t j) { return (p * tile + j) * tile + i; };
    double mean = 0;
    for (std::size_t j = 1; j + 1 < tile; ++j)
      for (std::size_t i = 1; i + 1 < tile; ++i)
        mean += details[at(i, j)][2];
    mean /= double((tile - 2) * (tile - 2));
    for (std::size_t j = 1; j + 1 < tile; ++j)
      for (std::size_t i = 1; i + 1 < tile; ++i)
        h[at(i, j)] = details[at(i, j)][2] - mean;
  }
  return h;
}

//! Root mean square and the 5% and 95% quantiles.
std::array<double, 3> spread(std::vector<double> v)
{
  double sum = 0;
  for (const double x : v)
    sum += x * x;
  std::sort(v.begin(), v.end());
  return {std::sqrt(sum / double(v.size())), v[v.size() / 20], v[v.size() - 1 - v.size() / 20]};
}

TEST(Multires, ACoarseEditKeepsTheBumpsAndMakesTheEdit)
{
  // A bumpy sphere whose top is pulled up at edit level 2 (bump wavelength
  // about half a face of that level). Where the pull moved the surface, the
  // distribution of bump heights after must match the one before: RMS and
  // the 5% and 95% quantiles within 10% of the RMS.
  PaintSurface surface(test::runtime(), test::noisy_sphere(3, 0.f), kLevel, AtlasStorage::Buffer);
  Atlas& atlas = surface.atlas();
  std::vector<Float4> fine = atlas.read_positions(kLevel);
  add_bumps(fine, 0.02f);
  atlas.write_positions(kLevel, fine);
  surface.geometry_changed();
  const std::vector<double> heights_before = bump_heights(atlas, 2);
  const std::vector<Float4> before = atlas.read_limit_positions();

  const Vec3 centre{0.f, 0.f, 1.f};
  const float radius = 1.2f, lift = 0.4f;
  Stroke grab = make_stroke(Tool::Grab);
  grab.points = {centre, {centre[0], centre[1], centre[2] + lift}};
  grab.brush.radius = radius;
  grab.set_edit_level(2);
  const StrokeReport report = surface.apply(grab);
  EXPECT_GE(report.dabs_applied, 1u);
  const std::vector<Float4> after = atlas.read_limit_positions();
  const std::vector<double> heights_after = bump_heights(atlas, 2);

  std::vector<double> h0, h1;
  for (std::size_t t = 0; t < before.size(); ++t)
    if (!std::isnan(heights_before[t]) && distance(after[t], before[t]) > 0.5 * lift) {
      h0.push_back(heights_before[t]);
      h1.push_back(heights_after[t]);
    }
  ASSERT_GT(h0.size(), 1000u);
  const auto s0 = spread(h0), s1 = spread(h1);
  std::printf("bump heights where moved (%zu texels): RMS %.4g -> %.4g, 5%% %.4g -> %.4g, 95%% %.4g -> %.4g\n",
              h0.size(), s0[0], s1[0], s0[1], s1[1], s0[2], s1[2]);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(s1[k], s0[k], 0.1 * s0[0]) << "measure " << k;

  // The pull itself: the top moved up by the lift (weight 1 at the centre),
  // nothing far from the brush moved at all, and the copies agree.
  std::size_t top = 0;
  for (std::size_t t = 0; t < before.size(); ++t)
    if (before[t][2] > before[top][2])
      top = t;
  EXPECT_NEAR(after[top][2] - before[top][2], lift, 0.05 * lift);
  for (std::size_t t = 0; t < before.size(); ++t)
    if (distance(before[t], {centre[0], centre[1], centre[2], 0.f}) > radius + 1.0)
      ASSERT_EQ(std::memcmp(&before[t], &after[t], sizeof(Float4)), 0) << "texel " << t;
  EXPECT_EQ(test::differing_copies(atlas.topology(), atlas.layout(kLevel), atlas.read_positions(kLevel)), 0u);
  EXPECT_LT(report.stretch, 2.f);
}

TEST(Multires, UndoOfCoarseAndFineEditsIsBitExact)
{
  PaintSurface surface(test::runtime(), test::noisy_sphere(3, 0.02f), 4, AtlasStorage::Buffer);
  const std::vector<Float4> start = surface.atlas().read_positions(4);
  const std::vector<Float4> start_limit = surface.atlas().read_limit_positions();
  surface.apply(coarse_inflate({0.f, 0.f, 1.f}, 0.6f, 0.2f, 2));
  const StrokeScript script = parse_stroke_script(R"({"strokes": [
      {"tool": "smooth", "points": [[1, 0, 0]], "radius": 0.5, "edit_level": 3, "iterations": 3},
      {"tool": "sculpt", "points": [[0, 1, 0]], "radius": 0.4, "amount": 0.1},
      {"tool": "grab", "points": [[0, 0, -1], [0.1, 0, -1.3]], "radius": 0.5, "edit_level": 2}]})");
  for (const Stroke& s : script.strokes)
    surface.apply(s);
  const std::vector<Float4> edited = surface.atlas().read_positions(4);
  EXPECT_FALSE(same_bits(edited, start));
  for (int k = 0; k < 4; ++k)
    ASSERT_TRUE(surface.undo());
  EXPECT_TRUE(same_bits(surface.atlas().read_positions(4), start));
  EXPECT_TRUE(same_bits(surface.atlas().read_limit_positions(), start_limit));
  for (int k = 0; k < 4; ++k)
    ASSERT_TRUE(surface.redo());
  EXPECT_TRUE(same_bits(surface.atlas().read_positions(4), edited));
}

// The brush's patches come from the finest surface, but a coarse edit weighs
// the edit level's smoother surface, whose texels on the sides shared with
// patches outside the brush may fall inside the radius. They must stay put:
// moving the copies in the brush's patches and not the others would part
// the edit level's surface there.
TEST(Multires, CoarseEditsKeepTheEditLevelsCopiesEqual)
{
  PaintSurface surface(test::runtime(), test::noisy_sphere(3, 0.05f), 4, AtlasStorage::Buffer);
  const StrokeScript script = parse_stroke_script(R"({"strokes": [
      {"tool": "inflate", "points": [[0, 0, 1]], "radius": 0.7, "amount": 0.2, "edit_level": 2},
      {"tool": "sculpt", "points": [[0, 1, 0]], "radius": 0.6, "amount": 0.15, "edit_level": 2},
      {"tool": "smooth", "points": [[0, 1, 0]], "radius": 0.6, "iterations": 2, "edit_level": 2},
      {"tool": "grab", "points": [[1, 0, 0], [1.2, 0.1, 0]], "radius": 0.6, "edit_level": 3}]})");
  for (const Stroke& s : script.strokes) {
    surface.apply(s);
    for (const int level : {2, 3, 4})
      EXPECT_EQ(test::differing_copies(surface.atlas().topology(), surface.atlas().layout(level),
                                       surface.atlas().read_positions(level)),
                0u)
        << tool_name(s.tool) << " at edit level " << s.edit_level() << ": level " << level;
  }
}

TEST(Multires, DeviceBytesAreWhatItAllocates)
{
  // The plan checked before the first coarse edit, against the driver's
  // sizes of what the constructor allocates: at levels 2 and 3 (on CPUs
  // without a layer for U) and at level 4.
  for (const int level : {2, 3, 4}) {
    Atlas atlas(test::runtime(), test::noisy_sphere(2, 0.f), level, AtlasStorage::Buffer);
    const Multires multires(atlas);
    EXPECT_EQ(multires.allocated_bytes(), Multires::device_bytes(atlas)) << "level " << level;
    EXPECT_EQ(Multires::device_bytes(atlas),
              Multires::device_bytes(atlas.topology().patch_count, level, atlas.storage(),
                                     AtlasEvaluator::patch_items_on(atlas.runtime().info())))
      << "level " << level;
  }
}

TEST(Multires, BufferAndImageStorageAgreeBitForBit)
{
  std::vector<Float4> result[2];
  for (const AtlasStorage storage : {AtlasStorage::Buffer, AtlasStorage::Image}) {
    PaintSurface surface(test::runtime(), test::noisy_sphere(3, 0.02f), 4, storage);
    surface.apply(coarse_inflate({0.f, 0.f, 1.f}, 0.6f, 0.2f, 2));
    Stroke grab = coarse_inflate({1.f, 0.f, 0.f}, 0.5f, 0.f, 1);
    grab.tool = Tool::Grab;
    grab.points.push_back({1.2f, 0.1f, 0.f});
    surface.apply(grab);
    result[storage == AtlasStorage::Image] = surface.atlas().read_positions(4);
  }
  EXPECT_TRUE(same_bits(result[0], result[1]));
}

TEST(Multires, GrabPullsTheRegionAlongThePath)
{
  for (const int edit_level : {-1, 2}) {
    PaintSurface surface(test::runtime(), test::flat_grid(8), 4, AtlasStorage::Buffer);
    const std::vector<Float4> before = surface.atlas().read_limit_positions();
    Stroke grab = make_stroke(Tool::Grab);
    grab.points = {{4.f, 4.f, 0.f}, {4.f, 4.f, 0.5f}, {4.f, 4.f, 1.f}};
    grab.brush.radius = 2.f;
    grab.brush.falloff = FALLOFF_CONSTANT;
    grab.set_edit_level(edit_level);
    const StrokeReport report = surface.apply(grab);
    EXPECT_GT(report.dabs_applied, 1u);
    const std::vector<Float4> after = surface.atlas().read_limit_positions();
    for (std::size_t t = 0; t < before.size(); ++t) {
      const double from_centre = std::hypot(before[t][0] - 4.0, before[t][1] - 4.0);
      if (from_centre < 0.5)
        ASSERT_NEAR(after[t][2], 1.0, edit_level < 0 ? 1e-5 : 0.05) << "texel " << t << " at " << from_centre;
      if (from_centre > 3.5)
        ASSERT_EQ(after[t][2], before[t][2]) << "texel " << t << " at " << from_centre;
    }
  }
}

TEST(Multires, StretchTellsWhenTheEditLevelIsTooCoarse)
{
  PaintSurface surface(test::runtime(), test::flat_grid(8), 4, AtlasStorage::Buffer);
  Stroke pull = make_stroke(Tool::Grab);
  pull.points = {{4.f, 4.f, 0.f}, {4.f, 4.f, 0.05f}};
  pull.brush.radius = 1.5f;
  pull.set_edit_level(1);
  EXPECT_LT(surface.apply(pull).stretch, 1.2f);
  pull.points = {{4.f, 4.f, 0.05f}, {4.f, 4.f, 6.f}};
  EXPECT_GT(surface.apply(pull).stretch, 2.f);
}

// Encoding measures each tile's extent as it encodes it (on CPUs) and
// stretch() measures it again with patch_extent: with nothing moved since,
// the two must be the same bits, so no patch grew.
TEST(Multires, StretchRightAfterEncodingIsOne)
{
  BumpyAtlas b;
  Multires multires(b.atlas);
  for (const int edit : {1, 3}) {
    multires.encode(edit);
    EXPECT_EQ(multires.stretch(every_patch(b.atlas)), 1.f) << "edit level " << edit;
  }
}

// CPUs encode a finest level 2 or 3 as its last subdivision step makes it
// (subdivide_encode_*), a finer one eight patches per work item
// (encode_patches, a patch per lane), and decode a patch per work item
// (decode_patches), GPUs a work item per texel (encode_details with
// patch_extent, decode_tiles): the same details,
// extents and rebuilt texels, bit for bit, on every test shape (patch
// counts that leave lanes over) and tile size. Positions with x > 0 are
// scaled down to where a frame's normal is too short to divide by, so that
// lanes of both of frame_of()'s cases meet in one work item.
TEST(Multires, PerPatchKernelsAgreeWithPerTexel)
{
  for (const std::string& name : test::shape_names())
    for (int finest = 2; finest <= 4; ++finest) {
      const BaseMesh mesh = test::shape(name);
      Atlas lanes(test::runtime(), mesh, finest, AtlasStorage::Buffer);
      Atlas texels(test::runtime(), mesh, finest, AtlasStorage::Buffer);
      lanes.set_patch_items(true);
      texels.set_patch_items(false);
      lanes.subdivide(1, finest);
      std::vector<Float4> fine = lanes.read_positions(finest);
      add_bumps(fine, 0.02f);
      for (Float4& t : fine) // a function of the position: every copy alike
        if (t[0] > 0.f)
          for (int k = 0; k < 3; ++k)
            t[k] *= 1e-9f;
      for (Atlas* a : {&lanes, &texels})
        a->write_positions(finest, fine);
      Multires by_lanes(lanes), by_texels(texels);
      for (const int edit : {1, finest - 1}) {
        by_lanes.encode(edit);
        by_texels.encode(edit);
        EXPECT_TRUE(same_bits(by_lanes.read_details(), by_texels.read_details()))
          << name << ", level " << finest << " from " << edit;
        // The extents measured while encoding, against patch_extent's.
        EXPECT_EQ(by_lanes.stretch(every_patch(lanes)), 1.f) << name << ", level " << finest << " from " << edit;
        // Every third patch's reach rebuilt after the edit level moved.
        std::vector<int> moved;
        for (int p = 0; p < lanes.layout(edit).patches; p += 3)
          moved.push_back(p);
        std::vector<Float4> base = lanes.read_positions(edit);
        for (Float4& t : base)
          t[2] += 0.01f * t[0];
        for (Atlas* a : {&lanes, &texels})
          a->write_positions(edit, base);
        by_lanes.reconstruct(by_lanes.reach(moved));
        by_texels.reconstruct(by_texels.reach(moved));
        const std::vector<Float4> rebuilt = lanes.read_positions(finest);
        EXPECT_TRUE(same_bits(rebuilt, texels.read_positions(finest)))
          << name << ", level " << finest << " rebuilt from " << edit;
        EXPECT_TRUE(std::all_of(rebuilt.begin(), rebuilt.end(), [](const Float4& t) {
          return std::isfinite(t[0]) && std::isfinite(t[1]) && std::isfinite(t[2]);
        })) << name << ": the comparison is of numbers";
      }
    }
}

TEST(Multires, EditLevelFinerThanTheSurfaceIsRefused)
{
  PaintSurface surface(test::runtime(), test::flat_grid(4), 3, AtlasStorage::Buffer);
  Stroke s = coarse_inflate({2.f, 2.f, 0.f}, 1.f, 0.1f, 4);
  EXPECT_THROW(surface.apply(s), InputError);
  EXPECT_TRUE(surface.history().empty());
}

TEST(Multires, LevelOfDetailCarriesTheFinestNormals)
{
  PaintSurface surface(test::runtime(), test::noisy_sphere(3, 0.f), 4, AtlasStorage::Buffer);
  const PaintedSurface full = surface.painted_surface();
  EXPECT_EQ(surface.painted_surface(4).surface.points.size(), full.surface.points.size());
  for (const int lod : {1, 2, 3}) {
    const PaintedSurface coarse = surface.painted_surface(lod);
    const LevelLayout l = surface.atlas().layout(lod);
    EXPECT_EQ(coarse.surface.quads.size(), std::size_t(l.patches) * l.n * l.n);
    EXPECT_LT(coarse.surface.points.size(), full.surface.points.size());
    ASSERT_EQ(coarse.surface.normals.size(), coarse.surface.points.size());
    for (const Vec3& n : coarse.surface.normals)
      ASSERT_NEAR(length_of(n), 1.0, 1e-5);
    // Every coarse vertex has the normal of some finest vertex.
    ASSERT_EQ(coarse.diffuse.size(), coarse.surface.points.size());
  }
  EXPECT_THROW(surface.painted_surface(5), InputError);
}

} // namespace
} // namespace meshpaint
