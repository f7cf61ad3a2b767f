// Projects: saving and loading bit for bit, and refusing damaged files.

#include "core/errors.h"
#include "core/format.h"
#include "project/project.h"
#include "project/project_surface.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <cmath>      // for std::nanf, std::isfinite
#include <cstdio>     // for std::remove
#include <cstring>    // for std::memcmp
#include <filesystem> // for std::filesystem
#include <fstream>    // for std::ifstream, std::ofstream
#include <functional> // for std::function
#include <iterator>   // for std::istreambuf_iterator
#include <unistd.h>   // for getpid

namespace meshpaint {
namespace {

namespace fs = std::filesystem;

std::vector<char> file_bytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void put_bytes(const fs::path& path, const std::vector<char>& bytes)
{
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

//! The message load_project() refuses a file with, or "" when it loads.
std::string load_error(const fs::path& path)
{
  try {
    load_project(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

Project captured(PaintSurface& s, const std::string& history = "")
{
  Project p;
  p.history = history;
  capture_surface(s, p);
  return p;
}

bool same_texels(const std::vector<Float4>& a, const std::vector<Float4>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Float4)) == 0;
}

class ProjectTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    dir_ = fs::temp_directory_path() / ("meshpaint_project_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  //! A painted, sculpted surface of mixed polygons at level 3.
  std::unique_ptr<PaintSurface> painted()
  {
    auto s = std::make_unique<PaintSurface>(test::runtime(), test::mixed_polygons(), 3, AtlasStorage::Buffer);
    Stroke paint;
    paint.points = {{0.f, 0.f, 1.f}, {0.5f, 0.2f, 1.f}};
    paint.brush.radius = 0.6f;
    paint.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.2f, 0.1f, 1.f};
    paint.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
    paint.paint().value[CHANNEL_LABEL] = {3.f, 0.f, 0.f, 1.f};
    paint.paint().alpha[CHANNEL_LABEL] = 1.f;
    s->apply(paint);
    Stroke sculpt = make_stroke(Tool::Sculpt);
    sculpt.points = {{0.f, 0.f, 1.f}};
    sculpt.brush.radius = 0.5f;
    sculpt.move().amount = 0.05f;
    s->apply(sculpt);
    return s;
  }

  Project sample(PaintSurface& s)
  {
    ScanReference scan;
    scan.path = "scans/a.off";
    scan.bytes = 1234;
    scan.crc32 = 0xdeadbeef;
    Project p;
    p.labels = {{3, "tumour", {1.f, 0.f, 0.f}}, {7, "bone", {0.9f, 0.9f, 0.8f}}};
    p.history = R"({"strokes": []})";
    p.scan = scan;
    capture_surface(s, p);
    p.reference = p.positions;
    p.reference[5][1] += 1.f;
    return p;
  }

  fs::path dir_;
};

TEST_F(ProjectTest, RoundTripIsBitForBit)
{
  auto surface = painted();
  const Project saved = sample(*surface);
  const fs::path path = dir_ / "a.meshpaint";
  save_project(saved, path.string());
  const Project loaded = load_project(path.string());

  EXPECT_EQ(loaded.mesh.name, saved.mesh.name);
  EXPECT_EQ(loaded.mesh.points, saved.mesh.points);
  EXPECT_EQ(loaded.mesh.face_sizes, saved.mesh.face_sizes);
  EXPECT_EQ(loaded.mesh.face_offsets, saved.mesh.face_offsets);
  EXPECT_EQ(loaded.mesh.face_vertices, saved.mesh.face_vertices);
  EXPECT_EQ(loaded.level, 3);
  EXPECT_TRUE(same_texels(loaded.positions, saved.positions));
  EXPECT_TRUE(same_texels(loaded.channels.diffuse, saved.channels.diffuse));
  EXPECT_TRUE(same_texels(loaded.channels.specular, saved.channels.specular));
  EXPECT_TRUE(same_texels(loaded.channels.material, saved.channels.material));
  EXPECT_TRUE(same_texels(loaded.reference, saved.reference));
  ASSERT_EQ(loaded.labels.size(), 2u);
  EXPECT_EQ(loaded.labels[1].id, 7);
  EXPECT_EQ(loaded.labels[1].name, "bone");
  EXPECT_EQ(loaded.labels[1].colour, (Vec3{0.9f, 0.9f, 0.8f}));
  EXPECT_EQ(loaded.history, saved.history);
  EXPECT_EQ(loaded.scan.path, "scans/a.off");
  EXPECT_EQ(loaded.scan.bytes, 1234u);
  EXPECT_EQ(loaded.scan.crc32, 0xdeadbeefu);

  // The surface rebuilt from the file is the painted one: same atlas (patch
  // order), same control points, channels and limit surface, and saving it
  // again gives the same bytes.
  auto reopened = open_project_surface(test::runtime(), loaded, AtlasStorage::Buffer);
  EXPECT_EQ(reopened->atlas().base_mesh().face_vertices, surface->atlas().base_mesh().face_vertices);
  EXPECT_TRUE(same_texels(reopened->atlas().read_positions(3), surface->atlas().read_positions(3)));
  EXPECT_TRUE(same_texels(reopened->atlas().read_limit_positions(), surface->atlas().read_limit_positions()));
  EXPECT_TRUE(same_texels(reopened->atlas().read_limit_normals(), surface->atlas().read_limit_normals()));
  EXPECT_TRUE(same_texels(reopened->read_channels().material, surface->read_channels().material));
  const fs::path again = dir_ / "b.meshpaint";
  Project resaved = loaded;
  capture_surface(*reopened, resaved);
  save_project(resaved, again.string());
  EXPECT_EQ(file_bytes(again), file_bytes(path));
}

TEST_F(ProjectTest, RebuildsTheAtlasOfAnUnorderedInput)
{
  // The atlas sorts faces spatially; the project stores them sorted, and a
  // second sort must keep that order, or the texels would land on other patches.
  const BaseMesh scan = test::genus_two();
  PaintSurface s(test::runtime(), scan, 2, AtlasStorage::Buffer);
  bool reordered = false;
  for (std::size_t f = 0; f < s.atlas().base_face_order().size(); ++f)
    reordered |= s.atlas().base_face_order()[f] != int(f);
  EXPECT_TRUE(reordered) << "the shape should need reordering for this test to mean anything";
  const fs::path path = dir_ / "g.meshpaint";
  save_project(captured(s), path.string());
  auto reopened = open_project_surface(test::runtime(), load_project(path.string()), AtlasStorage::Buffer);
  EXPECT_TRUE(same_texels(reopened->atlas().read_limit_positions(), s.atlas().read_limit_positions()));
}

TEST(ReferenceAtLevel, RefinesAndReducesAFitAsTheSurfaceItStandsFor)
{
  // A "fit" that is the cube's level-2 subdivision moved by 0.5 along x:
  // refined to level 3 it is the level-3 subdivision moved the same
  // (subdivision is affine), where the unmoved one would not be.
  PaintSurface surface(test::runtime(), test::cube(), 2, AtlasStorage::Buffer);
  Project project;
  capture_surface(surface, project);
  project.reference = surface.atlas().read_positions(2);
  for (Float4& q : project.reference)
    q[0] += 0.5f;
  const std::vector<Float4> finer = reference_at_level(test::runtime(), project, 3, AtlasStorage::Buffer);
  PaintSurface fine(test::runtime(), project.mesh, 3, AtlasStorage::Buffer);
  const std::vector<Float4> expected = fine.atlas().read_positions(3);
  ASSERT_EQ(finer.size(), expected.size());
  std::size_t moved = 0;
  for (std::size_t t = 0; t < finer.size(); ++t) {
    if (expected[t][0] == 0.f && expected[t][1] == 0.f && expected[t][2] == 0.f)
      continue; // no texel of a patch
    ASSERT_NEAR(finer[t][0], expected[t][0] + 0.5f, 1e-5f) << "texel " << t;
    ASSERT_NEAR(finer[t][1], expected[t][1], 1e-5f) << "texel " << t;
    ASSERT_NEAR(finer[t][2], expected[t][2], 1e-5f) << "texel " << t;
    ++moved;
  }
  EXPECT_GT(moved, finer.size() / 2);
  // Reduced: the coarser level's texels, all finite.
  const std::vector<Float4> coarser = reference_at_level(test::runtime(), project, 1, AtlasStorage::Buffer);
  EXPECT_EQ(coarser.size(), surface.atlas().layout(1).texels());
  for (const Float4& q : coarser)
    ASSERT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2]));
}

TEST_F(ProjectTest, TruncatedFilesAreRefused)
{
  auto surface = painted();
  const fs::path path = dir_ / "t.meshpaint";
  save_project(sample(*surface), path.string());
  const std::vector<char> bytes = file_bytes(path);
  for (const std::size_t keep : {std::size_t(0), std::size_t(5), std::size_t(20), std::size_t(40), bytes.size() / 2,
                                 bytes.size() - 1}) {
    const fs::path cut = dir_ / "cut.meshpaint";
    put_bytes(cut, std::vector<char>(bytes.begin(), bytes.begin() + std::ptrdiff_t(keep)));
    const std::string error = load_error(cut);
    EXPECT_NE(error, "") << "kept " << keep << " bytes";
    if (keep >= 8)
      EXPECT_NE(error.find("truncated project"), std::string::npos) << error;
  }
}

TEST_F(ProjectTest, EveryFlippedByteIsRefused)
{
  // A small project, so every byte can be tried.
  PaintSurface s(test::runtime(), test::tetrahedron(), 1, AtlasStorage::Buffer);
  const fs::path path = dir_ / "f.meshpaint";
  Project p = captured(s, "{}");
  p.labels = {{1, "a", {1.f, 1.f, 1.f}}};
  save_project(p, path.string());
  const std::vector<char> bytes = file_bytes(path);
  const fs::path bad = dir_ / "bad.meshpaint";
  for (std::size_t k = 0; k < bytes.size(); ++k) {
    std::vector<char> flipped = bytes;
    flipped[k] = char(flipped[k] ^ 0x10);
    put_bytes(bad, flipped);
    EXPECT_NE(load_error(bad), "") << "byte " << k;
  }
}

TEST_F(ProjectTest, NewerVersionsAndOtherFilesAreRefusedByName)
{
  PaintSurface s(test::runtime(), test::tetrahedron(), 1, AtlasStorage::Buffer);
  const fs::path path = dir_ / "v.meshpaint";
  save_project(captured(s), path.string());
  std::vector<char> bytes = file_bytes(path);
  bytes[8] = char(kProjectVersion + 1); // the version, little-endian
  put_bytes(path, bytes);
  EXPECT_EQ(load_error(path), path.string() + ": project format version 2 is newer than this meshpaint reads (up to 1); "
                                              "open it with a newer meshpaint");
  put_bytes(path, {'o', 'f', 'f', '\n', '0'});
  EXPECT_EQ(load_error(path), path.string() + ": not a meshpaint project (no project signature at the start)");
  EXPECT_THROW(load_project((dir_ / "missing.meshpaint").string()), IOError);
}

TEST_F(ProjectTest, AFailedSaveKeepsThePreviousFile)
{
  PaintSurface s(test::runtime(), test::tetrahedron(), 1, AtlasStorage::Buffer);
  const fs::path path = dir_ / "keep.meshpaint";
  save_project(captured(s, "first"), path.string());
  Project broken = captured(s, "second");
  broken.channels.diffuse.pop_back(); // refused while writing
  EXPECT_THROW(save_project(broken, path.string()), InputError);
  EXPECT_EQ(load_project(path.string()).history, "first");
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir_))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 1u) << "no temporary left behind";
}

TEST_F(ProjectTest, ALabelNameThatIsNotUtf8IsRefused)
{
  auto surface = painted();
  Project p = sample(*surface);
  p.labels[1].name = "bo\xffne";
  const fs::path path = dir_ / "bad-name.meshpaint";
  save_project(p, path.string());
  try {
    load_project(path.string());
    FAIL() << "loaded a label name that is not UTF-8";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"name\" \"bo\\xffne\" is not valid UTF-8"), std::string::npos) << e.what();
  }
}

TEST_F(ProjectTest, ContentIsCheckedNotOnlyChecksums)
{
  // Each file below has valid checksums (save_project() writes them): what
  // is refused is what it holds.
  auto surface = painted();
  const auto refused = [&](const char* name, const std::function<void(Project&)>& damage) {
    Project p = sample(*surface);
    damage(p);
    const fs::path path = dir_ / name;
    save_project(p, path.string());
    return load_error(path);
  };
  EXPECT_NE(refused("nan.meshpaint", [](Project& p) { p.positions[3][0] = std::nanf(""); })
              .find("corrupt project (control point 3 has the value nan"),
            std::string::npos);
  EXPECT_NE(refused("huge.meshpaint", [](Project& p) { p.reference[0][2] = 3e38f; })
              .find("corrupt project (reference point 0 has the value 3e+38"),
            std::string::npos);
  EXPECT_NE(refused("label.meshpaint", [](Project& p) { p.channels.material[2][2] = 2.5f; })
              .find("corrupt project (label at texel 2 is not an integer"),
            std::string::npos);
  EXPECT_NE(refused("mask.meshpaint", [](Project& p) { p.channels.material[2][3] = -0.5f; })
              .find("corrupt project (mask at texel 2 is not from 0 to 1"),
            std::string::npos);
  EXPECT_NE(refused("classes.meshpaint", [](Project& p) { p.labels[1].id = 3; })
              .find("corrupt project (label 1: id 3 is used twice)"),
            std::string::npos);
  EXPECT_NE(refused("face.meshpaint",
                    [](Project& p) { p.mesh.face_vertices[1] = p.mesh.face_vertices[0]; })
              .find("corrupt project (the base mesh needs repairs"),
            std::string::npos);
  // What the sample holds as saved loads.
  EXPECT_EQ(refused("fine.meshpaint", [](Project&) {}), "");
}

TEST(Labels, ParsedAndChecked)
{
  const auto labels = parse_labels(R"([{"id": 1, "name": "femur", "colour": [1, 0.5, 0]},
                                       {"id": 2, "name": "tibia", "colour": [0, 0, 1]}])");
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_EQ(labels[0].name, "femur");
  EXPECT_EQ(labels[0].colour, (Vec3{1.f, 0.5f, 0.f}));
  const auto error = [](const std::string& text) {
    try {
      parse_labels(text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(R"({"id": 1})"), "labels must be a JSON array of {\"id\", \"name\", \"colour\"} objects");
  EXPECT_EQ(error(R"([{"id": 1, "name": "a", "colour": [1, 0, 0]}, {"id": 1, "name": "b", "colour": [1, 0, 0]}])"),
            "label 1: id 1 is used twice");
  EXPECT_EQ(error(R"([{"id": 1, "name": "a", "colour": [1, 0, 0]}, {"id": 2, "name": "a", "colour": [1, 0, 0]}])"),
            "label 1: name \"a\" is used twice");
  EXPECT_EQ(error(R"([{"id": -1, "name": "a", "colour": [1, 0, 0]}])"),
            "label 0: \"id\" must be an integer from 0 to 16777216");
  EXPECT_EQ(error(R"([{"id": 1, "name": "a", "colour": [2, 0, 0]}])"),
            "label 0: \"colour\" must be [r, g, b] with numbers from 0 to 1");
  EXPECT_EQ(error(R"([{"id": 1, "name": "", "colour": [1, 0, 0]}])"), "label 0: \"name\" must be a non-empty string");
  EXPECT_EQ(error(R"([{"id": 1, "name": "a", "color": [1, 0, 0]}])"),
            "label 0: unknown key \"color\" (id, name, colour)");
  EXPECT_NE(error("[{"), "");
  // A huge unknown key is quoted only in part.
  const std::string huge(100000, 'k');
  const std::string said = error(R"([{"id": 1, ")" + huge + R"(": 0}])");
  EXPECT_LT(said.size(), 200u) << said.substr(0, 300);
  EXPECT_NE(said.find("... (100000 bytes)"), std::string::npos) << said.substr(0, 300);
}

TEST(Text, Utf8AndExcerpts)
{
  EXPECT_TRUE(is_utf8(""));
  EXPECT_TRUE(is_utf8("f\xc3\xa9mur \xe2\x82\xac \xf0\x9f\xa6\xb4"));
  EXPECT_FALSE(is_utf8("\xff"));
  EXPECT_FALSE(is_utf8("\xc3"));             // cut short
  EXPECT_FALSE(is_utf8("\xc0\xaf"));         // overlong '/'
  EXPECT_FALSE(is_utf8("\xed\xa0\x80"));     // a surrogate
  EXPECT_FALSE(is_utf8("\xf4\x90\x80\x80")); // beyond U+10FFFF
  EXPECT_EQ(excerpt("a\nb"), "a\\x0ab");
  EXPECT_EQ(excerpt("b\xffz\xc3\xa9"), "b\\xffz\\xc3\\xa9"); // not UTF-8: every byte beyond ASCII escaped
  EXPECT_EQ(excerpt("abcdef", 3), "abc... (6 bytes)");
  EXPECT_EQ(excerpt("ab\xc3\xa9", 3), "ab... (4 bytes)"); // not inside the two-byte e-acute
}

} // namespace
} // namespace meshpaint
