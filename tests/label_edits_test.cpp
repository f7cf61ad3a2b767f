// Label edits: locked classes, painting only over one class, fill and merge.

#include "core/errors.h"
#include "paint/paint_surface.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cmath>  // for std::sqrt, std::lround
#include <string> // for std::string

namespace meshpaint {
namespace {

//! Applies every stroke of a stroke script.
void apply_script(PaintSurface& surface, const std::string& json)
{
  for (const Stroke& s : parse_stroke_script(json).strokes)
    surface.apply(s);
}

std::vector<float> labels_of(PaintSurface& surface)
{
  std::vector<float> out;
  for (const Float4& m : surface.read_channels().material)
    out.push_back(m[2]);
  return out;
}

double planar_distance(const Float4& p, double x, double y) { return std::sqrt((p[0] - x) * (p[0] - x) + (p[1] - y) * (p[1] - y)); }

//! Whether the script is refused with a message holding `words`.
bool refused(const std::string& json, const std::string& words)
{
  try { parse_stroke_script(json); } catch (const InputError& e) { return std::string(e.what()).find(words) != std::string::npos; }
  return false;
}

class LabelEdits : public ::testing::TestWithParam<AtlasStorage>
{
};

TEST_P(LabelEdits, ALockedClassIsNeverOverwritten)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, GetParam());
  apply_script(surface, R"({"strokes": [
    {"tool": "label", "points": [[2, 3, 0]], "radius": 1, "falloff": "constant", "channels": {"label": 3}}]})");
  const std::vector<float> before = labels_of(surface);
  // Label paint and a wash of the label channel, both told class 3 is locked.
  apply_script(surface, R"({"strokes": [
    {"tool": "label", "points": [[1, 3, 0], [5, 3, 0]], "radius": 2, "falloff": "constant",
     "channels": {"label": 5}, "locked_labels": [9, 3]},
    {"tool": "wash", "channels": {"label": 6}, "locked_labels": [3, 5]}]})");
  const std::vector<float> after = labels_of(surface);
  std::size_t kept = 0, washed = 0;
  for (std::size_t t = 0; t < after.size(); ++t) {
    if (before[t] == 3.f) {
      ASSERT_EQ(after[t], 3.f) << "texel " << t;
      ++kept;
    } else {
      ASSERT_TRUE(after[t] == 5.f || after[t] == 6.f) << "texel " << t << " is " << after[t];
      washed += after[t] == 6.f;
    }
  }
  EXPECT_GT(kept, 100u);
  EXPECT_GT(washed, 100u);
}

TEST_P(LabelEdits, OnlyOverChangesOnlyTheChosenClass)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, GetParam());
  apply_script(surface, R"({"strokes": [
    {"tool": "label", "points": [[2, 3, 0]], "radius": 1, "falloff": "constant", "channels": {"label": 3}}]})");
  const std::vector<float> before = labels_of(surface);
  // Over class 3: 3 becomes 4; then over unlabelled surface: 0 becomes 7.
  apply_script(surface, R"({"strokes": [
    {"tool": "label", "points": [[3, 3, 0]], "radius": 2, "falloff": "constant", "channels": {"label": 4},
     "only_over_label": 3},
    {"tool": "label", "points": [[3, 3, 0]], "radius": 2, "falloff": "constant", "channels": {"label": 7},
     "only_over_label": 0}]})");
  const std::vector<float> after = labels_of(surface);
  const auto pos = surface.atlas().read_limit_positions();
  std::size_t fours = 0, sevens = 0;
  for (std::size_t t = 0; t < after.size(); ++t) {
    const bool brushed = planar_distance(pos[t], 3, 3) <= 2;
    const float expect = before[t] == 3.f ? (brushed ? 4.f : 3.f) : (brushed ? 7.f : 0.f);
    ASSERT_EQ(after[t], expect) << "texel " << t;
    fours += expect == 4.f;
    sevens += expect == 7.f;
  }
  EXPECT_GT(fours, 50u);
  EXPECT_GT(sevens, 50u);
}

TEST_P(LabelEdits, FillStopsAtOtherClassesAndCrossesPatchSides)
{
  // A band of class 2 across the grid at x = 3 splits the unlabelled
  // surface in two: a fill on the left fills the left only, every patch
  // of it (the band's edge is no straight texel line).
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, GetParam());
  apply_script(surface, R"({"strokes": [
    {"tool": "label", "points": [[3, 0, 0], [3, 6, 0]], "radius": 0.6, "falloff": "constant", "channels": {"label": 2}},
    {"tool": "label", "points": [[5, 5, 0]], "radius": 0.5, "falloff": "constant", "channels": {"label": 8}}]})");
  const std::vector<float> before = labels_of(surface);
  apply_script(surface, R"({"strokes": [{"tool": "fill", "points": [[1, 3, 0.2]], "radius": 0.5, "channels": {"label": 4}}]})");
  const std::vector<float> after = labels_of(surface);
  const auto pos = surface.atlas().read_limit_positions();
  std::size_t filled = 0;
  for (std::size_t t = 0; t < after.size(); ++t) {
    const bool left = pos[t][0] < 3.f;
    ASSERT_EQ(after[t], before[t] == 0.f && left ? 4.f : before[t]) << "texel " << t << " at x " << pos[t][0];
    filled += after[t] == 4.f;
  }
  EXPECT_GT(filled, after.size() / 4);
  // A fill of class 2 over the band, told it may only go over class 8: nothing.
  apply_script(surface, R"({"strokes": [{"tool": "fill", "points": [[3, 3, 0]], "radius": 0.5, "channels": {"label": 9},
    "only_over_label": 8}]})");
  EXPECT_EQ(labels_of(surface), after);
  // Undo gives the bits back.
  ASSERT_TRUE(surface.undo());
  ASSERT_TRUE(surface.undo());
  EXPECT_EQ(labels_of(surface), before);
}

TEST_P(LabelEdits, FillCoversAClosedSurfaceThroughEveryCorner)
{
  // The cube's corners are extraordinary (valence 3): the region crosses
  // sides and corners of all its patches.
  PaintSurface surface(test::runtime(), test::cube(), 3, GetParam());
  apply_script(surface, R"({"strokes": [{"tool": "fill", "points": [[0.5, 0.5, 2]], "radius": 2, "channels": {"label": 5}}]})");
  for (const float l : labels_of(surface))
    ASSERT_EQ(l, 5.f);
  // A locked seed class fills nothing.
  apply_script(surface, R"({"strokes": [{"tool": "fill", "points": [[0.5, 0.5, 2]], "radius": 2, "channels": {"label": 1},
    "locked_labels": [5]}]})");
  for (const float l : labels_of(surface))
    ASSERT_EQ(l, 5.f);
}

TEST_P(LabelEdits, ADiagonalFillCrossesALineOfTexelsTouchingAtCorners)
{
  // A staircase of class 2 along the grid's diagonal (texel x index equal
  // to texel y index) touches itself only at corners: it splits the surface
  // for a fill along sides, and lets a fill across corners through.
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, GetParam());
  const auto pos = surface.atlas().read_limit_positions();
  const auto on_line = [&](std::size_t t) {
    return std::lround(pos[t][0] * 16.f) == std::lround(pos[t][1] * 16.f);
  };
  PaintChannels channels = surface.read_channels();
  std::size_t line = 0;
  for (std::size_t t = 0; t < pos.size(); ++t)
    if (on_line(t)) {
      channels.material[t][2] = 2.f;
      ++line;
    }
  ASSERT_GT(line, 0u);
  surface.write_channels(channels);
  const std::vector<float> before = labels_of(surface);
  apply_script(surface, R"({"strokes": [{"tool": "fill", "points": [[4, 1, 0]], "radius": 0.5, "channels": {"label": 5}}]})");
  std::vector<float> after = labels_of(surface);
  for (std::size_t t = 0; t < after.size(); ++t)
    ASSERT_EQ(after[t], before[t] == 0.f && pos[t][0] > pos[t][1] ? 5.f : before[t]) << "texel " << t;
  ASSERT_TRUE(surface.undo());
  EXPECT_EQ(labels_of(surface), before);
  apply_script(surface, R"({"strokes": [{"tool": "fill", "points": [[4, 1, 0]], "radius": 0.5, "channels": {"label": 5},
    "connect": "diagonals"}]})");
  after = labels_of(surface);
  for (std::size_t t = 0; t < after.size(); ++t)
    ASSERT_EQ(after[t], on_line(t) ? 2.f : 5.f) << "texel " << t;
  EXPECT_TRUE(surface.history().back().paint().fill_diagonals);
}

TEST_P(LabelEdits, MergeTurnsOneClassIntoAnother)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, GetParam());
  apply_script(surface, R"({"strokes": [
    {"tool": "label", "points": [[2, 3, 0]], "radius": 1, "falloff": "constant", "channels": {"label": 3}},
    {"tool": "label", "points": [[4.5, 3, 0]], "radius": 1, "falloff": "constant", "channels": {"label": 5}},
    {"tool": "paint", "points": [[2, 3, 0]], "radius": 0.5, "falloff": "constant", "channels": {"mask": 1}}]})");
  const std::vector<float> before = labels_of(surface);
  // Locked: nothing; then merged, masked texels included.
  apply_script(surface, R"({"strokes": [{"tool": "merge", "only_over_label": 3, "channels": {"label": 5},
    "locked_labels": [3]}]})");
  EXPECT_EQ(labels_of(surface), before);
  apply_script(surface, R"({"strokes": [{"tool": "merge", "only_over_label": 3, "channels": {"label": 5}}]})");
  const std::vector<float> after = labels_of(surface);
  std::size_t merged = 0;
  for (std::size_t t = 0; t < after.size(); ++t) {
    ASSERT_EQ(after[t], before[t] == 3.f ? 5.f : before[t]) << "texel " << t;
    merged += before[t] == 3.f;
  }
  EXPECT_GT(merged, 100u);
  EXPECT_EQ(surface.history().back().tool, Tool::Merge);
}

INSTANTIATE_TEST_SUITE_P(BothStorages, LabelEdits, ::testing::Values(AtlasStorage::Buffer, AtlasStorage::Image));

TEST(LabelEditScripts, KeysReadBackAndAreRefusedWhereMeaningless)
{
  const std::string script = R"({"strokes": [
    {"tool": "label", "points": [[0, 0, 0]], "radius": 1, "channels": {"label": 5}, "locked_labels": [1, 2],
     "only_over_label": 0},
    {"tool": "fill", "points": [[0, 0, 0]], "radius": 1, "channels": {"label": 4}, "locked_labels": [3]},
    {"tool": "merge", "only_over_label": 3, "channels": {"label": 5}}]})";
  const StrokeScript s = parse_stroke_script(script);
  ASSERT_EQ(s.strokes.size(), 3u);
  EXPECT_EQ(s.strokes[0].paint().locked_labels, (std::vector<int>{1, 2}));
  EXPECT_EQ(s.strokes[0].paint().only_over_label, 0);
  EXPECT_EQ(s.strokes[1].tool, Tool::Fill);
  EXPECT_EQ(s.strokes[2].tool, Tool::Merge);
  const StrokeScript back = parse_stroke_script(stroke_script_json(s));
  ASSERT_EQ(back.strokes.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(back.strokes[k], s.strokes[k]) << "stroke " << k;

  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "sculpt", "points": [[0, 0, 0]], "radius": 1, "amount": 0.1,
    "locked_labels": [1]}]})", "\"locked_labels\" has no meaning"));
  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "paint", "points": [[0, 0, 0]], "radius": 1,
    "channels": {"diffuse": [1, 0, 0]}, "only_over_label": 1}]})", "\"only_over_label\" has no meaning"));
  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "label", "points": [[0, 0, 0]], "radius": 1,
    "channels": {"label": 1}, "locked_labels": [-1]}]})", "class ids from 0"));
  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "fill", "points": [[0, 0, 0], [1, 0, 0]], "radius": 1,
    "channels": {"label": 1}}]})", "one point"));
  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "merge", "channels": {"label": 1}}]})", "is required for a merge"));
  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "label", "points": [[0, 0, 0]], "radius": 1,
    "channels": {"label": 1}, "connect": "diagonals"}]})", "connect"));
  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "fill", "points": [[0, 0, 0]], "radius": 1,
    "channels": {"label": 1}, "connect": "corners"}]})", "sides, diagonals"));
  // The default is not written, so recordings without the key read and write the same.
  const std::string sides = stroke_script_json(parse_stroke_script(R"({"strokes": [{"tool": "fill",
    "points": [[0, 0, 0]], "radius": 1, "channels": {"label": 1}, "connect": "sides"}]})"));
  EXPECT_EQ(sides.find("connect"), std::string::npos);
  const StrokeScript diagonal = parse_stroke_script(R"({"strokes": [{"tool": "fill", "points": [[0, 0, 0]],
    "radius": 1, "channels": {"label": 1}, "connect": "diagonals"}]})");
  EXPECT_EQ(parse_stroke_script(stroke_script_json(diagonal)).strokes.at(0), diagonal.strokes.at(0));
  EXPECT_TRUE(diagonal.strokes.at(0).paint().fill_diagonals);
  EXPECT_TRUE(refused(R"({"strokes": [{"tool": "merge", "only_over_label": 2, "points": [[0, 0, 0]],
    "channels": {"label": 1}}]})", "has no meaning"));
}

} // namespace
} // namespace meshpaint
