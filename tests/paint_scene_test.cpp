// Scenes of several objects: strokes that cross from one object to another
// in contact, parameter-space dabs that stay on one, undo on all.

#include "paint/paint_scene.h"
#include "core/errors.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

namespace meshpaint {
namespace {

//! Two 4 x 4 plates side by side in z = 0, touching along x = 4.
PaintScene two_plates()
{
  PaintScene scene;
  BaseMesh right = test::flat_grid(4);
  for (Vec3& p : right.points)
    p[0] += 4.f; // positions only: the faces stay as they are
  scene.add(std::make_unique<PaintSurface>(test::runtime(), test::flat_grid(4), 3, AtlasStorage::Buffer), "left");
  scene.add(std::make_unique<PaintSurface>(test::runtime(), right, 3, AtlasStorage::Buffer), "right");
  return scene;
}

std::size_t painted(PaintSurface& s)
{
  std::size_t n = 0;
  for (const Float4& d : s.read_channels().diffuse)
    n += d[0] == 1.f && d[1] == 0.f;
  return n;
}

Stroke red_line(int space)
{
  Stroke s;
  s.points = {{2.f, 2.f, 0.f}, {6.f, 2.f, 0.f}};
  s.brush.radius = 0.5f;
  s.brush.falloff = FALLOFF_CONSTANT;
  s.brush.space = space;
  s.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  return s;
}

TEST(PaintScene, AStrokeAcrossTheContactPaintsBothObjects)
{
  for (const int space : {SPACE_OBJECT, SPACE_TANGENT}) {
    PaintScene scene = two_plates();
    const std::vector<StrokeReport> r = scene.apply(red_line(space));
    ASSERT_EQ(r.size(), 2u);
    EXPECT_FALSE(r[0].left_surface);
    EXPECT_GT(painted(scene.surface(0)), 100u);
    EXPECT_GT(painted(scene.surface(1)), 100u);
    EXPECT_TRUE(scene.undo());
    EXPECT_EQ(painted(scene.surface(0)), 0u);
    EXPECT_EQ(painted(scene.surface(1)), 0u);
  }
}

TEST(PaintScene, AParameterSpaceDabPaintsOneObject)
{
  PaintScene scene = two_plates();
  Stroke s = red_line(SPACE_PARAMETER);
  s.points = {{4.2f, 2.05f, 0.f}}; // nearer the right plate, within reach of both
  s.brush.radius = 0.3f;
  scene.apply(s);
  EXPECT_EQ(painted(scene.surface(0)), 0u);
  EXPECT_GT(painted(scene.surface(1)), 0u);
}

TEST(PaintScene, AStrokeEndsWhereNoObjectIsUnderIt)
{
  PaintScene scene = two_plates();
  Stroke s = red_line(SPACE_OBJECT);
  s.points = {{2.f, 2.f, 0.f}, {2.f, 6.f, 0.f}, {6.f, 6.f, 0.f}, {6.f, 2.f, 0.f}}; // off both plates, then back
  const std::vector<StrokeReport> r = scene.apply(s);
  EXPECT_TRUE(r[0].left_surface);
  EXPECT_GT(painted(scene.surface(0)), 0u);
  EXPECT_EQ(painted(scene.surface(1)), 0u);
}

TEST(PaintScene, NamesFoldersAndOneLevel)
{
  PaintScene scene = two_plates();
  scene.add(std::make_unique<PaintSurface>(test::runtime(), test::flat_grid(2), 3, AtlasStorage::Buffer), "left");
  scene.add(std::make_unique<PaintSurface>(test::runtime(), test::flat_grid(2), 3, AtlasStorage::Buffer), "");
  EXPECT_EQ(scene.name(2), "left_2");
  EXPECT_EQ(scene.name(3), "object");
  EXPECT_EQ(scene.folder("out", 1), "out/right");
  EXPECT_THROW(scene.add(std::make_unique<PaintSurface>(test::runtime(), test::flat_grid(2), 2, AtlasStorage::Buffer),
                         "coarse"),
               InputError);
  EXPECT_EQ(scene.size(), 4u);
  // every object records every stroke, so the first one's history is the scene's
  scene.apply(red_line(SPACE_PARAMETER));
  EXPECT_EQ(scene.history().size(), 1u);
  EXPECT_EQ(scene.surface(3).history().size(), 1u);
  PaintScene one;
  EXPECT_TRUE(one.history().empty());
  one.add(std::make_unique<PaintSurface>(test::runtime(), test::flat_grid(2), 3, AtlasStorage::Buffer), "alone");
  EXPECT_EQ(one.folder("out", 0), "out");
}

} // namespace
} // namespace meshpaint
