// The window's brush makes its strokes directly (no JSON per mouse move):
// for every tool, channel, swatch, op, falloff, mirror, space and edit level
// the keys reach, the stroke is what its script form reads back as, so a
// recording of the window replays exactly.

#include "BrushSettings.h"

#include <gtest/gtest.h>

namespace meshpaint {
namespace {

Camera a_camera()
{
  Camera c;
  c.position = {0.f, -3.f, 1.f};
  c.view_angle = 35.f;
  return c;
}

TEST(BrushSettings, EveryKeyCombinationMakesAStrokeThatReadsBackAsItself)
{
  const std::vector<Vec3> path = {{0.1f, 0.2f, 0.3f}, {0.4f, 0.25f, 0.3f}};
  BrushSettings brush(2.5, 4);
  brush.set_camera(a_camera());
  std::size_t made = 0;
  for (int tool = 0; tool < 9; ++tool, brush.handle_key("t", false))
    for (int space = 0; space < 4; ++space, brush.handle_key("p", false))
      for (int channel = 0; channel < 6; ++channel, brush.handle_key("c", false))
        for (const char* swatch : {"0", "5", "9"}) {
          brush.handle_key(swatch, false);
          brush.handle_key("o", false);   // the next op
          brush.handle_key("f", false);   // the next falloff
          brush.handle_key("m", false);   // the next mirror
          brush.handle_key("i", false);   // in and out
          brush.handle_key("l", channel % 2 == 1); // the edit level down or up
          const Stroke s = brush.stroke(path);
          SCOPED_TRACE(stroke_json(s));
          EXPECT_EQ(parse_stroke_script("{\"strokes\": [" + stroke_json(s) + "]}").strokes.front(), s);
          EXPECT_NO_THROW(check_stroke(s));
          EXPECT_EQ(s.points, path);
          ++made;
        }
  EXPECT_EQ(made, 9u * 4 * 6 * 3);
}

TEST(BrushSettings, CheckStrokeRefusesWhatAScriptWould)
{
  Stroke s = make_stroke(Tool::Paint);
  s.points = {{0.f, 0.f, 0.f}};
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  s.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  EXPECT_THROW(check_stroke(s), InputError); // no radius
  s.brush.radius = 0.1f;
  EXPECT_NO_THROW(check_stroke(s));
  s.paint().value[CHANNEL_DIFFUSE][0] = 2.f; // outside 0..1
  EXPECT_THROW(check_stroke(s), InputError);
  s.paint().value[CHANNEL_DIFFUSE][0] = 1.f;
  s.brush.space = SPACE_SCREEN; // without the view it is drawn in
  EXPECT_THROW(check_stroke(s), InputError);
}

} // namespace
} // namespace meshpaint
