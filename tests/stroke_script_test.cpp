// Stroke scripts written back out: what parse_stroke_script() reads from
// stroke_script_json() is the same script, and a surface's history of
// strokes follows undo and redo.

#include "paint/paint_surface.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cstring> // for std::memcmp
#include <fstream> // for std::ifstream
#include <sstream> // for std::ostringstream

namespace meshpaint {
namespace {

//! Every tool, op, mode and option of the format at least once.
const char* const kEveryKind = R"({"level": 3, "strokes": [
  {"tool": "paint", "points": [[0, 0, 1], [0.5, 0.1, 0.9]], "radius": 0.3, "strength": 0.7, "falloff": "gaussian",
   "spacing": 0.4, "op": "over", "channels": {"diffuse": [0.9, 0.2, 0.1, 0.5], "roughness": 0.3},
   "alphas": {"diffuse": 0.25}, "pressure": [0.5, 1.0], "mirror": "x"},
  {"tool": "paint", "points": [[0, 0, 1]], "radius": 0.2, "op": "max", "channels": {"displacement": -0.01},
   "pattern": {"type": "marble", "scale": 3.5, "octaves": 5, "matte": "opaque",
               "transform": [[0, 1, 0, 0.25], [1, 0, 0, 0], [0, 0, 1, 0.1]]}},
  {"tool": "paint", "points": [[0, 0, 1]], "radius": 0.2, "mode": "polish", "coefficient": 0.8},
  {"tool": "paint", "points": [[0, 0, 1]], "radius": 0.2, "mode": "sandpaper"},
  {"tool": "paint", "points": [[0, 0, 1]], "radius": 0.2, "mode": "remover"},
  {"tool": "paint", "points": [[0, 0, 1]], "radius": 0.2, "mode": "dye", "channels": {"specular": [0.1, 0.2, 0.3]}},
  {"tool": "paint", "points": [[0, 0, 1], [1, 0, 0], [0, 1, 0]], "radius": 0.2, "stroke": "rubberband",
   "op": "subtract", "channels": {"mask": 1}},
  {"tool": "label", "points": [[0, 0, 1]], "radius": 0.2, "channels": {"label": 7}, "stroke": "rubberstamp"},
  {"tool": "wash", "channels": {"diffuse": [0.5, 0.5, 0.5]}, "op": "add", "strength": 0.1},
  {"tool": "dip", "channels": {"diffuse": [0, 0, 1]}, "pattern": {"type": "bath", "coord": "position"}},
  {"tool": "paint", "points": [[0, 0, 1]], "radius": 0.2, "channels": {"diffuse": [1, 1, 0]},
   "pattern": {"type": "noise", "coord": "uv", "scale": 8}},
  {"tool": "smooth", "points": [[1, 0, 0]], "radius": 0.5, "iterations": 4, "lambda": 0.4, "mu": -0.45,
   "edit_level": 2},
  {"tool": "smooth", "points": [[1, 0, 0]], "radius": 0.5, "target": "color", "method": "laplacian", "mu": -0.2},
  {"tool": "blur", "points": [[1, 0, 0]], "radius": 0.5, "iterations": 2},
  {"tool": "paint", "op": "blur", "points": [[1, 0, 0]], "radius": 0.5},
  {"tool": "sculpt", "points": [[0, 1, 0]], "radius": 0.4, "amount": -0.05, "edit_level": 1},
  {"tool": "inflate", "points": [[0, 1, 0]], "radius": 0.4, "amount": 0.02},
  {"tool": "flatten", "points": [[0, 1, 0]], "radius": 0.4, "amount": 0.3},
  {"tool": "smear", "points": [[0, 1, 0], [0, 0.8, 0.6]], "radius": 0.4, "strength": 0.6},
  {"tool": "grab", "points": [[0, -1, 0], [0, -1.2, 0.1]], "radius": 0.4, "edit_level": 2},
  {"tool": "paint", "points": [[0, 0, 1], [0.2, 0, 0.95]], "radius": 0.3, "space": "screen", "backfaces": "paint",
   "camera": {"position": [0, 0, 5], "focal_point": [0, 0, 0], "view_up": [0, 1, 0], "view_angle": 25},
   "channels": {"diffuse": [0, 1, 0]}, "pattern": {"type": "turbulence", "coord": "screen", "scale": 2}},
  {"tool": "paint", "points": [[1, 0, 0]], "radius": 0.3, "space": "tangent", "channels": {"roughness": 0.9}},
  {"tool": "label", "points": [[0, 0, 1]], "radius": 0.4, "space": "screen", "channels": {"label": 9},
   "camera": {"position": [0, 0, 5], "focal_point": [0, 0, 0], "view_up": [0, 1, 0]},
   "spray": {"drops": 16, "size": 0.05, "seed": 7}},
  {"tool": "paint", "points": [[1, 0, 0]], "radius": 0.05, "space": "parameter", "channels": {"label": 3}},
  {"tool": "sculpt", "points": [[0, 0, -1]], "radius": 0.3, "space": "tangent", "amount": 0.02}
]})";

void expect_round_trip(const StrokeScript& script)
{
  const std::string text = stroke_script_json(script);
  const StrokeScript back = parse_stroke_script(text);
  EXPECT_EQ(back.level, script.level);
  ASSERT_EQ(back.strokes.size(), script.strokes.size());
  for (std::size_t k = 0; k < script.strokes.size(); ++k)
    EXPECT_TRUE(back.strokes[k] == script.strokes[k]) << "stroke " << k << " became " << stroke_json(back.strokes[k])
                                                      << "\nfrom " << stroke_json(script.strokes[k]);
  EXPECT_EQ(stroke_script_json(back), text);
}

TEST(StrokeScript, EveryKindOfStrokeReadsBackTheSame) { expect_round_trip(parse_stroke_script(kEveryKind)); }

TEST(StrokeScript, TheBundledDemoReadsBackTheSame)
{
  std::ifstream in(std::string(MESHPAINT_SOURCE_DIR) + "/data/strokes/bunny_demo.json");
  ASSERT_TRUE(in);
  std::ostringstream text;
  text << in.rdbuf();
  expect_round_trip(parse_stroke_script(text.str()));
}

TEST(StrokeScript, NumbersSurviveExactly)
{
  StrokeScript script = parse_stroke_script(R"({"strokes": [{"tool": "sculpt", "points": [[0, 0, 0]],
      "radius": 1, "amount": 1}]})");
  Stroke& s = script.strokes[0];
  s.points = {{0.1f, 1.f / 3.f, -7.0000005f}, {1e-30f, 1234.5678f, 0.f}};
  s.brush.radius = 0.123456789f;
  s.move().amount = -2.5e-8f;
  expect_round_trip(script);
}

TEST(StrokeScript, ABrushKeepsOnlyTheKeysItsToolReads)
{
  const std::string brush = drop_meaningless_keys(
    R"({"tool": "grab", "points": [[0, 0, 0]], "radius": 1, "amount": 0.1, "iterations": 3, "op": "over",
        "channels": {"diffuse": [1, 0, 0]}, "edit_level": 2})");
  const StrokeScript script = parse_stroke_script("{\"strokes\": [" + brush + "]}");
  EXPECT_EQ(script.strokes[0].tool, Tool::Grab);
  EXPECT_EQ(script.strokes[0].edit_level(), 2);
  // A bad value is not a key to drop: it is still reported.
  const std::string bad = drop_meaningless_keys(R"({"tool": "sculpt", "points": [[0, 0, 0]], "radius": -1, "amount": 1})");
  EXPECT_THROW(parse_stroke_script("{\"strokes\": [" + bad + "]}"), InputError);
  EXPECT_EQ(drop_meaningless_keys("not json"), "not json");
}

TEST(StrokeScript, HistoryFollowsUndoAndRedo)
{
  PaintSurface surface(test::runtime(), test::flat_grid(4), 3, AtlasStorage::Buffer);
  const StrokeScript script = parse_stroke_script(R"({"strokes": [
      {"tool": "paint", "points": [[1, 1, 0]], "radius": 0.5, "channels": {"diffuse": [1, 0, 0]}},
      {"tool": "paint", "points": [[9, 9, 5]], "radius": 0.5, "channels": {"diffuse": [0, 1, 0]}},
      {"tool": "sculpt", "points": [[2, 2, 0]], "radius": 0.5, "amount": 0.1}]})");
  for (const Stroke& s : script.strokes)
    surface.apply(s); // the second leaves the surface at once: still a step
  ASSERT_EQ(surface.history().size(), 3u);
  EXPECT_TRUE(surface.undo());
  EXPECT_TRUE(surface.undo());
  ASSERT_EQ(surface.history().size(), 1u);
  EXPECT_TRUE(surface.history()[0] == script.strokes[0]);
  EXPECT_TRUE(surface.redo());
  ASSERT_EQ(surface.history().size(), 2u);
  EXPECT_TRUE(surface.history()[1] == script.strokes[1]);
  surface.apply(script.strokes[2]);
  EXPECT_FALSE(surface.redo());
  EXPECT_EQ(surface.history().size(), 3u);
}

TEST(StrokeScript, ReplayAfterUndoingBetweenCoarseStrokesIsExact)
{
  const StrokeScript script = parse_stroke_script(R"({"strokes": [
      {"tool": "inflate", "points": [[0, 0, 1]], "radius": 0.6, "amount": 0.1, "edit_level": 1},
      {"tool": "grab", "points": [[1, 0, 0], [1.2, 0, 0.1]], "radius": 0.5, "edit_level": 1},
      {"tool": "sculpt", "points": [[0, 1, 0]], "radius": 0.5, "amount": 0.05, "edit_level": 1}]})");
  PaintSurface live(test::runtime(), test::noisy_sphere(3, 0.02f), 3, AtlasStorage::Buffer);
  live.apply(script.strokes[0]);
  live.apply(script.strokes[1]);
  ASSERT_TRUE(live.undo());
  live.apply(script.strokes[2]);
  PaintSurface replay(test::runtime(), test::noisy_sphere(3, 0.02f), 3, AtlasStorage::Buffer);
  for (const Stroke& s : parse_stroke_script(stroke_script_json({3, live.history()})).strokes)
    replay.apply(s);
  const std::vector<Float4> a = live.atlas().read_positions(3), b = replay.atlas().read_positions(3);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Float4)), 0);
}

TEST(StrokeScript, ReplayingTheHistoryGivesTheSameSurface)
{
  const StrokeScript script = parse_stroke_script(kEveryKind);
  const auto run = [](const std::vector<Stroke>& strokes) {
    PaintSurface surface(test::runtime(), test::noisy_sphere(3, 0.01f), 3, AtlasStorage::Buffer);
    for (const Stroke& s : strokes)
      surface.apply(s);
    return std::make_pair(surface.atlas().read_positions(3), surface.read_channels().diffuse);
  };
  PaintSurface live(test::runtime(), test::noisy_sphere(3, 0.01f), 3, AtlasStorage::Buffer);
  for (const Stroke& s : script.strokes)
    if (!s.pattern() || (s.pattern()->kind != PATTERN_IMAGE && s.pattern()->kind != PATTERN_VOLUME))
      live.apply(s);
  const auto replayed = run(parse_stroke_script(stroke_script_json({3, live.history()})).strokes);
  const std::vector<Float4> positions = live.atlas().read_positions(3), diffuse = live.read_channels().diffuse;
  EXPECT_EQ(std::memcmp(replayed.first.data(), positions.data(), positions.size() * sizeof(Float4)), 0);
  EXPECT_EQ(std::memcmp(replayed.second.data(), diffuse.data(), diffuse.size() * sizeof(Float4)), 0);
}

} // namespace
} // namespace meshpaint
