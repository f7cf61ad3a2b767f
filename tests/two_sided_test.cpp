// Two-sided materials: an inside set of colours and roughness, painted from
// the side the brush is on, exported as a second material.

#include "paint/model_export.h"
#include "paint/paint_surface.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cstdio>     // for std::remove
#include <filesystem> // for std::filesystem
#include <fstream>    // for std::ifstream
#include <sstream>    // for std::ostringstream

namespace meshpaint {
namespace {

Stroke colour_dab(const Vec3& at, Float4 colour)
{
  Stroke s;
  s.points = {at};
  s.brush.radius = 1.f;
  s.brush.falloff = FALLOFF_CONSTANT;
  s.paint().value[CHANNEL_DIFFUSE] = colour;
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  return s;
}

TEST(TwoSided, EachSideIsPaintedFromItsOwnSide)
{
  PaintSurface surface(test::runtime(), test::flat_grid(4), 3, AtlasStorage::Buffer);
  surface.set_two_sided(true);
  // The plane's normal is +z: a brush above paints the outside, below the inside.
  surface.apply(colour_dab({2.f, 2.f, 0.2f}, {1.f, 0.f, 0.f, 1.f}));
  Stroke below = colour_dab({2.f, 2.f, -0.2f}, {0.f, 0.f, 1.f, 1.f});
  below.paint().value[CHANNEL_LABEL] = {5.f, 5.f, 5.f, 1.f}; // labels belong to the surface, not a side
  below.paint().alpha[CHANNEL_LABEL] = 1.f;
  surface.apply(below);
  const PaintChannels c = surface.read_channels();
  ASSERT_EQ(c.inside_diffuse.size(), c.diffuse.size());
  std::size_t red_out = 0, blue_in = 0, crossed = 0, labelled = 0;
  for (std::size_t t = 0; t < c.diffuse.size(); ++t) {
    red_out += c.diffuse[t][0] == 1.f && c.diffuse[t][2] == 0.f;
    blue_in += c.inside_diffuse[t][2] == 1.f && c.inside_diffuse[t][0] == 0.f;
    crossed += c.diffuse[t][2] == 1.f || c.inside_diffuse[t][0] == 1.f;
    labelled += c.material[t][2] == 5.f;
  }
  EXPECT_GT(red_out, 20u);
  EXPECT_EQ(blue_in, red_out); // the same footprint, on the other side
  EXPECT_EQ(crossed, 0u);
  EXPECT_EQ(labelled, red_out);
  const PaintedSurface out = surface.painted_surface();
  EXPECT_EQ(out.inside_diffuse.size(), out.diffuse.size());
  EXPECT_EQ(out.inside_roughness.size(), out.roughness.size());
  // Undo takes both sides back.
  EXPECT_TRUE(surface.undo());
  EXPECT_TRUE(surface.undo());
  for (const Float4& d : surface.read_channels().inside_diffuse)
    ASSERT_EQ(d[2], 0.8f);
}

TEST(TwoSided, ExportedAsTwoMaterials)
{
  PaintSurface surface(test::runtime(), test::flat_grid(4), 3, AtlasStorage::Buffer);
  surface.set_two_sided(true);
  Stroke inside = colour_dab({2.f, 2.f, 0.f}, {0.f, 1.f, 0.f, 1.f});
  inside.brush.side = 2;
  surface.apply(inside);
  ExportModel model;
  TextureMaps maps;
  build_export(surface, 2, model, maps);
  ASSERT_EQ(maps.inside_diffuse.size(), maps.diffuse.size());
  const std::string dir = (std::filesystem::temp_directory_path() / "meshpaint_two_sided").string();
  std::filesystem::create_directories(dir);
  write_obj_model(model, maps, dir);
  std::ifstream mtl(dir + "/model.mtl"), obj(dir + "/model.obj");
  std::ostringstream m, o;
  m << mtl.rdbuf();
  o << obj.rdbuf();
  EXPECT_NE(m.str().find("newmtl inside"), std::string::npos);
  EXPECT_NE(m.str().find("map_Kd inside_diffuse.png"), std::string::npos);
  EXPECT_NE(o.str().find("usemtl inside"), std::string::npos);
  std::size_t faces = 0;
  for (std::size_t at = o.str().find("\nf "); at != std::string::npos; at = o.str().find("\nf ", at + 1))
    ++faces;
  EXPECT_EQ(faces, 2 * model.mesh.quads.size());
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace meshpaint
