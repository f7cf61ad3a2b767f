// StrokeSession: a stroke drawn by hand, point by point, paints the bits of
// the same path applied whole (what a replay of the recording does), for
// every tool family, with a mirror, on two objects; undo, redo and the
// recording.

#include "paint/stroke_session.h"
#include "core/errors.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cmath>   // for std::sin, std::cos
#include <cstring> // for std::memcmp

namespace meshpaint {
namespace {

std::shared_ptr<PaintSurface> sphere(AtlasStorage storage = AtlasStorage::Buffer)
{
  return std::make_shared<PaintSurface>(test::runtime(), test::noisy_sphere(6, 0.02f), 3, storage);
}

//! A wavy path over the sphere's upper half, as a hand draws it: many
//! points, closer than the dab spacing in places.
std::vector<Vec3> hand_path()
{
  std::vector<Vec3> path;
  for (int k = 0; k < 40; ++k) {
    const float t = 0.04f * float(k), a = 0.3f + 1.2f * t, b = 0.6f + 0.3f * std::sin(5.f * t);
    const float r = 0.97f; // near the limit surface, which lies inside the control points
    path.push_back({r * std::cos(a) * std::sin(b), r * std::sin(a) * std::sin(b), r * std::cos(b)});
  }
  return path;
}

Stroke with_tool(Tool tool)
{
  Stroke s = make_stroke(tool);
  s.points = hand_path();
  s.brush.radius = 0.15f;
  s.brush.strength = 0.8f;
  if (tool == Tool::Paint || tool == Tool::Label) {
    const int c = tool == Tool::Paint ? CHANNEL_DIFFUSE : CHANNEL_LABEL;
    s.paint().value[c] = tool == Tool::Paint ? Float4{1.f, 0.2f, 0.f, 1.f} : Float4{3.f, 3.f, 3.f, 1.f};
    s.paint().alpha[c] = 1.f;
  }
  if (tool == Tool::Sculpt || tool == Tool::Inflate)
    s.move().amount = 0.01f;
  if (tool == Tool::Flatten)
    s.move().amount = 0.5f;
  if (tool == Tool::Blur || tool == Tool::Smooth) {
    s.smooth().iterations = 2;
    s.smooth().target_colour = tool == Tool::Blur;
    s.smooth().taubin = tool == Tool::Smooth;
  }
  return s;
}

bool same_bits(const std::vector<Float4>& a, const std::vector<Float4>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Float4)) == 0;
}

void expect_same_surface(PaintSurface& a, PaintSurface& b)
{
  const PaintChannels ca = a.read_channels(), cb = b.read_channels();
  EXPECT_TRUE(same_bits(ca.diffuse, cb.diffuse));
  EXPECT_TRUE(same_bits(ca.specular, cb.specular));
  EXPECT_TRUE(same_bits(ca.material, cb.material));
  EXPECT_TRUE(same_bits(a.atlas().read_positions(a.level()), b.atlas().read_positions(b.level())));
  EXPECT_TRUE(same_bits(a.atlas().read_limit_positions(), b.atlas().read_limit_positions()));
}

//! Draws `stroke`'s path point by point into `session`.
std::vector<StrokeReport> draw(StrokeSession& session, const Stroke& stroke)
{
  Stroke first = stroke;
  first.points.resize(1);
  if (!first.pressure.empty())
    first.pressure.resize(1);
  session.begin(first);
  for (std::size_t k = 1; k < stroke.points.size(); ++k)
    session.extend(stroke.points[k], stroke.pressure.empty() ? 1.f : stroke.pressure[k]);
  EXPECT_EQ(session.current().points, stroke.points);
  return session.end();
}

TEST(StrokeSession, DrawnPointByPointPaintsTheBitsOfTheWholeStroke)
{
  // A painting first, so that blur, smear and smoothing have colours to move.
  const Stroke base = with_tool(Tool::Paint);
  for (const Tool tool : {Tool::Paint, Tool::Label, Tool::Blur, Tool::Smear, Tool::Smooth, Tool::Sculpt,
                          Tool::Inflate, Tool::Flatten, Tool::Grab}) {
    SCOPED_TRACE(tool_name(tool));
    Stroke stroke = with_tool(tool);
    if (tool == Tool::Paint) { // with a mirror, pressure and a stamp-less tangent brush
      stroke.brush.mirror_axis = 0;
      stroke.brush.space = SPACE_TANGENT;
      stroke.pressure.assign(stroke.points.size(), 1.f);
      stroke.pressure[5] = 0.8f;
    }
    if (tool == Tool::Sculpt)
      stroke.set_edit_level(2); // multiresolution: the coarser level moves, the finer follow
    PaintScene drawn_scene, whole_scene;
    drawn_scene.add(sphere(), "a");
    whole_scene.add(sphere(), "a");
    StrokeSession drawn(drawn_scene), whole(whole_scene);
    drawn.apply(base);
    whole.apply(base);
    const std::vector<StrokeReport> d = draw(drawn, stroke);
    const std::vector<StrokeReport> w = whole.apply(stroke);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].dabs, w[0].dabs);
    EXPECT_EQ(d[0].dabs_applied, w[0].dabs_applied);
    EXPECT_GT(d[0].dabs_applied, 0u);
    EXPECT_FALSE(d[0].left_surface);
    expect_same_surface(drawn_scene.surface(0), whole_scene.surface(0));
    // One undo step for the whole drag; the recording holds the whole path.
    EXPECT_EQ(drawn.recording(3).strokes.back(), stroke);
    EXPECT_TRUE(drawn.undo());
    EXPECT_TRUE(whole.undo());
    expect_same_surface(drawn_scene.surface(0), whole_scene.surface(0));
    EXPECT_EQ(drawn.recording(3).strokes.size(), 1u);
    EXPECT_TRUE(drawn.redo());
    EXPECT_EQ(drawn.recording(3).strokes.size(), 2u);
  }
}

TEST(StrokeSession, AReplayOfTheRecordingGivesTheSameBits)
{
  PaintScene scene, replayed;
  scene.add(sphere(), "a");
  replayed.add(sphere(), "a");
  StrokeSession session(scene);
  draw(session, with_tool(Tool::Paint));
  draw(session, with_tool(Tool::Sculpt));
  draw(session, with_tool(Tool::Smear));
  session.undo();
  draw(session, with_tool(Tool::Inflate));
  const StrokeScript script = parse_stroke_script(stroke_script_json(session.recording(3)));
  ASSERT_EQ(script.strokes.size(), 3u);
  StrokeSession replay(replayed);
  for (const Stroke& s : script.strokes)
    replay.apply(s);
  expect_same_surface(scene.surface(0), replayed.surface(0));
}

TEST(StrokeSession, TwoObjectsUnderAGeometryBrushMatchTheWholeStroke)
{
  // Previews while drawn, then the whole path applied once: the bits of a replay.
  const auto scene_of_two = [](PaintScene& scene) {
    scene.add(sphere(), "a");
    BaseMesh moved = test::noisy_sphere(6, 0.02f);
    for (Vec3& p : moved.points)
      p[0] += 1.9f;
    scene.add(std::make_shared<PaintSurface>(test::runtime(), moved, 3, AtlasStorage::Buffer), "b");
  };
  PaintScene drawn_scene, whole_scene;
  scene_of_two(drawn_scene);
  scene_of_two(whole_scene);
  Stroke stroke = with_tool(Tool::Sculpt);
  stroke.points = {{0.9f, 0.f, 0.3f}, {0.95f, 0.f, 0.2f}, {1.0f, 0.f, 0.1f}};
  stroke.brush.radius = 0.3f;
  StrokeSession drawn(drawn_scene), whole(whole_scene);
  draw(drawn, stroke);
  whole.apply(stroke);
  for (std::size_t o = 0; o < 2; ++o)
    expect_same_surface(drawn_scene.surface(o), whole_scene.surface(o));
  EXPECT_EQ(drawn.recording(3).strokes.size(), 1u);
}

//! Draws `stroke` as a hand does, expecting it refused for a non-finite
//! result: the message names it, nothing is being drawn after, the surface
//! is what it was before, and the recording has not grown.
void expect_drawn_stroke_refused(PaintScene& scene, const Stroke& stroke)
{
  StrokeSession session(scene);
  std::vector<std::vector<Float4>> before;
  for (std::size_t o = 0; o < scene.size(); ++o)
    before.push_back(scene.surface(o).atlas().read_positions(3));
  std::string message;
  try {
    draw(session, stroke);
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("refused: "), std::string::npos) << message;
  EXPECT_FALSE(session.drawing());
  EXPECT_TRUE(session.recording(3).strokes.empty());
  EXPECT_TRUE(scene.undone().empty()); // taken back for good: a redo would bring the refused result back
  for (std::size_t o = 0; o < scene.size(); ++o)
    EXPECT_TRUE(same_bits(scene.surface(o).atlas().read_positions(3), before[o])) << "object " << o;
  // The session goes on: the next stroke paints.
  Stroke next = with_tool(Tool::Paint);
  draw(session, next);
  EXPECT_EQ(session.recording(3).strokes.size(), 1u);
}

TEST(StrokeSession, ADrawnStrokeWithANonFiniteResultIsRefusedAndTakenBack)
{
  PaintScene scene;
  scene.add(sphere(), "a");
  Stroke stroke = with_tool(Tool::Sculpt);
  stroke.move().amount = 1e30f; // positions of 1e29 and beyond: non-finite limit normals
  expect_drawn_stroke_refused(scene, stroke);
}

TEST(StrokeSession, APreviewedStrokeWithANonFiniteResultIsRefusedAndTakenBack)
{
  PaintScene scene; // two objects: the geometry brush previews piece by piece
  scene.add(sphere(), "a");
  BaseMesh moved = test::noisy_sphere(6, 0.02f);
  for (Vec3& p : moved.points)
    p[0] += 1.9f;
  scene.add(std::make_shared<PaintSurface>(test::runtime(), moved, 3, AtlasStorage::Buffer), "b");
  Stroke stroke = with_tool(Tool::Inflate);
  stroke.points = {{0.9f, 0.f, 0.3f}, {0.95f, 0.f, 0.2f}, {1.0f, 0.f, 0.1f}};
  stroke.brush.radius = 0.3f;
  stroke.move().amount = 1e20f;
  expect_drawn_stroke_refused(scene, stroke);
}

TEST(StrokeSession, RefusesWhatCannotBeDone)
{
  PaintScene empty;
  StrokeSession none(empty);
  EXPECT_THROW(none.begin(with_tool(Tool::Paint)), InputError);
  PaintScene scene;
  scene.add(sphere(), "a");
  StrokeSession session(scene);
  EXPECT_THROW(session.end(), InputError);
  EXPECT_THROW(session.extend({0.f, 0.f, 1.f}), InputError);
  Stroke no_points = with_tool(Tool::Paint);
  no_points.points.clear();
  EXPECT_THROW(session.begin(no_points), InputError);
  session.begin(with_tool(Tool::Paint));
  EXPECT_THROW(session.begin(with_tool(Tool::Paint)), InputError);
  EXPECT_THROW(session.undo(), InputError);
  session.end();
  EXPECT_TRUE(session.undo());
  EXPECT_FALSE(session.undo());
}

TEST(StrokeSession, AStrokeThatLeavesTheSurfaceTakesNoMorePoints)
{
  PaintScene scene;
  scene.add(sphere(), "a");
  StrokeSession session(scene);
  Stroke s = with_tool(Tool::Paint);
  s.points = {{0.f, 0.f, 1.f}};
  session.begin(s);
  EXPECT_TRUE(session.extend({0.f, 0.05f, 1.f}));
  EXPECT_FALSE(session.extend({0.f, 0.f, 5.f})); // far off the surface
  EXPECT_FALSE(session.extend({0.f, 0.1f, 1.f}));
  EXPECT_EQ(session.current().points.size(), 3u);
  const std::vector<StrokeReport> r = session.end();
  EXPECT_TRUE(r[0].left_surface);
}

} // namespace
} // namespace meshpaint
