// Property tests of undo, redo and replay: random strokes of every tool,
// written as stroke-script JSON and parsed (so each is a stroke a user could
// write), with random undo and redo in between.
//  - Undoing everything gives back the atlas (control points and channels)
//    bit for bit.
//  - Replaying the strokes still applied, recorded with stroke_script_json()
//    and parsed back, on a fresh surface gives the same atlas bit for bit.
// And a long session: thousands of strokes stay within the undo budget.

#include "paint/paint_surface.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <algorithm> // for std::max
#include <cstring> // for std::memcmp
#include <fstream> // for std::ifstream
#include <random>  // for std::mt19937
#include <sstream> // for std::ostringstream
#include <string>  // for std::string
#include <unistd.h> // for sysconf

namespace meshpaint {
namespace {

//! What undo and replay must give back: the painting level's control points
//! and every channel.
struct AtlasState
{
  std::vector<Float4> positions;
  PaintChannels channels;
};

AtlasState read_state(PaintSurface& surface)
{
  return {surface.atlas().read_positions(surface.level()), surface.read_channels()};
}

bool same_bits(const std::vector<Float4>& a, const std::vector<Float4>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Float4)) == 0;
}

bool same_bits(const AtlasState& a, const AtlasState& b)
{
  return same_bits(a.positions, b.positions) && same_bits(a.channels.diffuse, b.channels.diffuse) &&
         same_bits(a.channels.specular, b.channels.specular) && same_bits(a.channels.material, b.channels.material);
}

//! Random strokes over the genus-two block (x 0..5, y 0..3, z 0..1), as JSON.
class StrokeMaker
{
public:
  explicit StrokeMaker(unsigned seed) : rng_(seed) {}

  std::string next()
  {
    static const char* const tools[] = {"paint", "label",   "wash",    "dip",   "smooth", "blur",
                                        "sculpt", "inflate", "flatten", "smear", "grab"};
    const std::string tool = tools[pick(11)];
    std::ostringstream s;
    s << "{\"tool\": \"" << tool << "\"";
    if (tool != "wash" && tool != "dip")
      s << ", \"points\": [" << point() << ", " << point() << "], \"radius\": " << number(0.3, 1.0);
    if (tool == "paint")
      s << ", \"op\": \"" << (const char* const[]){"copy", "over", "max", "add", "subtract"}[pick(5)]
        << "\", \"channels\": {\"diffuse\": [" << number(0, 1) << ", " << number(0, 1) << ", "
        << number(0, 1) << "], \"roughness\": " << number(0, 1) << ", \"displacement\": " << number(-0.05, 0.05)
        << "}, \"strength\": " << number(0.2, 1);
    else if (tool == "label")
      s << ", \"channels\": {\"label\": " << pick(8) << "}";
    else if (tool == "wash")
      s << ", \"channels\": {\"specular\": [" << number(0, 1) << ", 0.2, 0.3]}, \"strength\": " << number(0.1, 1);
    else if (tool == "dip")
      s << ", \"pattern\": {\"type\": \"bath\", \"transform\": [[0, 0, 1, " << number(-1, 0)
        << "], [0, 1, 0, 0], [1, 0, 0, 0]]}, \"channels\": {\"diffuse\": [0.1, 0.2, 0.9]}";
    else if (tool == "smooth" || tool == "blur")
      s << ", \"iterations\": " << 1 + pick(3);
    else if (tool == "sculpt" || tool == "inflate")
      s << ", \"amount\": " << number(-0.05, 0.05);
    else if (tool == "flatten")
      s << ", \"amount\": " << number(0, 1);
    else if (tool == "smear")
      s << ", \"strength\": " << number(0.5, 1);
    // Geometry at a coarser edit level too: the details it keeps across
    // strokes are part of what undo, redo and replay must give back.
    const bool moves = tool == "sculpt" || tool == "inflate" || tool == "flatten" || tool == "grab" || tool == "smooth";
    if (moves && pick(2) == 0)
      s << ", \"edit_level\": " << 1 + pick(2);
    s << "}";
    return s.str();
  }

  int pick(int n) { return int(rng_() % unsigned(n)); }

private:
  std::string number(double lo, double hi)
  {
    std::ostringstream s;
    s << lo + (hi - lo) * double(rng_() % 1000) / 1000.0;
    return s.str();
  }
  std::string point() { return "[" + number(0, 5) + ", " + number(0, 3) + ", " + number(0, 1) + "]"; }

  std::mt19937 rng_;
};

//! Resident set size of this process, from /proc/self/statm.
long resident_bytes()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

Stroke parse_one(const std::string& json)
{
  return parse_stroke_script("{\"strokes\": [" + json + "]}").strokes.at(0);
}

//! A random session on the genus-two block: strokes with random undo and
//! redo in between. Returns the number of strokes applied.
int random_session(PaintSurface& surface, unsigned seed)
{
  StrokeMaker maker(seed);
  int applied = 0;
  for (int step = 0; step < 40; ++step) {
    const int action = maker.pick(10);
    if (action < 2)
      surface.undo();
    else if (action < 3)
      surface.redo();
    else {
      const std::string json = maker.next();
      SCOPED_TRACE(json);
      surface.apply(parse_one(json));
      ++applied;
    }
  }
  return applied;
}

constexpr int kLevel = 3;

class UndoProperty : public testing::TestWithParam<unsigned>
{
};

TEST_P(UndoProperty, UndoAllRestoresAndReplayReproduces)
{
  PaintSurface surface(test::runtime(), test::genus_two(), kLevel, AtlasStorage::Buffer);
  const AtlasState start = read_state(surface);
  ASSERT_GT(random_session(surface, GetParam()), 0);
  ASSERT_EQ(surface.undo_log().undo_depth(), surface.history().size()) << "the budget forgot strokes";
  const AtlasState end = read_state(surface);

  // Replay what is still applied, through the recorded script.
  StrokeScript recorded;
  recorded.level = kLevel;
  recorded.strokes = surface.history();
  const StrokeScript replayed = parse_stroke_script(stroke_script_json(recorded));
  ASSERT_EQ(replayed.strokes.size(), surface.history().size());
  {
    PaintSurface fresh(test::runtime(), test::genus_two(), kLevel, AtlasStorage::Buffer);
    fresh.undo_log().set_recording(false);
    for (const Stroke& s : replayed.strokes)
      fresh.apply(s);
    EXPECT_TRUE(same_bits(read_state(fresh), end)) << "replaying " << replayed.strokes.size() << " strokes";
  }

  while (surface.undo()) {
  }
  EXPECT_TRUE(surface.history().empty());
  EXPECT_TRUE(same_bits(read_state(surface), start));
}

// Redoing as many strokes as were undone gives back the end of the session
// (a session may end with strokes of its own still to redo, so not "redo
// everything").
TEST_P(UndoProperty, RedoAfterUndoAllReproduces)
{
  PaintSurface surface(test::runtime(), test::genus_two(), kLevel, AtlasStorage::Buffer);
  random_session(surface, GetParam());
  const AtlasState end = read_state(surface);
  int undone = 0;
  while (surface.undo())
    ++undone;
  for (int k = 0; k < undone; ++k)
    ASSERT_TRUE(surface.redo());
  EXPECT_TRUE(same_bits(read_state(surface), end));
}

//! Writes the values of a partial read into the arrays of a full one.
void scatter(const PaintedVertices& update, PaintedSurface& shown)
{
  const PaintedSurface& v = update.values;
  for (std::size_t k = 0; k < update.ids.size(); ++k) {
    const std::size_t id = std::size_t(update.ids[k]);
    shown.surface.points[id] = v.surface.points[k];
    shown.surface.normals[id] = v.surface.normals[k];
    shown.diffuse[id] = v.diffuse[k];
    shown.specular[id] = v.specular[k];
    shown.roughness[id] = v.roughness[k];
    shown.displacement[id] = v.displacement[k];
    shown.mask[id] = v.mask[k];
    shown.label[id] = v.label[k];
    if (!v.inside_diffuse.empty()) {
      shown.inside_diffuse[id] = v.inside_diffuse[k];
      shown.inside_specular[id] = v.inside_specular[k];
      shown.inside_roughness[id] = v.inside_roughness[k];
    }
  }
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// A display that reads only the patches changed since it last looked
// (changes_since, painted_vertices) shows what a full read shows, bit for
// bit, after every action of a random session; odd seeds on a two-sided
// surface.
//! The bytes of each array of a full read, in the order of DisplayArrays.
std::vector<std::pair<const void*, std::size_t>> display_order(const PaintedSurface& s)
{
  const std::size_t n = s.surface.points.size(), v3 = 3 * sizeof(float) * n, v1 = sizeof(float) * n;
  std::vector<std::pair<const void*, std::size_t>> out{
    {s.surface.points.data(), v3}, {s.surface.normals.data(), v3}, {s.diffuse.data(), v3},
    {s.specular.data(), v3},       {s.roughness.data(), v1},       {s.displacement.data(), v1},
    {s.mask.data(), v1},           {s.label.data(), sizeof(int) * n}};
  if (!s.inside_diffuse.empty())
    out.insert(out.end(), {{s.inside_diffuse.data(), v3}, {s.inside_specular.data(), v3},
                           {s.inside_roughness.data(), v1}});
  return out;
}

//! The shared display arrays hold `full`, and flag every array that
//! differs from `before`.
void expect_display(const DisplayArrays& arrays, const PaintedSurface& full, const PaintedSurface& before)
{
  const auto now = display_order(full), was = display_order(before);
  ASSERT_EQ(arrays.arrays().size(), now.size());
  ASSERT_EQ(arrays.vertices(), full.surface.points.size());
  for (std::size_t k = 0; k < now.size(); ++k) {
    EXPECT_EQ(std::memcmp(arrays.data(k), now[k].first, now[k].second), 0) << arrays.arrays()[k].name;
    if (std::memcmp(was[k].first, now[k].first, now[k].second) != 0)
      EXPECT_TRUE(arrays.changed(k)) << arrays.arrays()[k].name << " changed without its flag";
  }
}

TEST_P(UndoProperty, DisplayFollowingChangesMatchesAFullRead)
{
  PaintSurface surface(test::runtime(), test::genus_two(), kLevel, AtlasStorage::Buffer);
  if (GetParam() % 2 == 1)
    surface.set_two_sided(true);
  PaintedSurface shown = surface.painted_surface();
  // Where the device's memory is the host's, the arrays a viewer draws
  // from in place follow the same changes.
  const std::shared_ptr<DisplayArrays> shared = surface.display_arrays();
  if (shared)
    expect_display(*shared, shown, shown);
  std::uint64_t seen = surface.change_count();
  StrokeMaker maker(GetParam());
  int partial = 0;
  for (int step = 0; step < 30; ++step) {
    const int action = maker.pick(10);
    std::string what = action < 2 ? "undo" : action < 3 ? "redo" : maker.next();
    SCOPED_TRACE(what);
    if (action < 2)
      surface.undo();
    else if (action < 3)
      surface.redo();
    else
      surface.apply(parse_one(what));
    const PatchChanges changes = surface.changes_since(seen);
    seen = surface.change_count();
    if (changes.all) {
      shown = surface.painted_surface();
      continue;
    }
    ++partial;
    EXPECT_LT(changes.patches.size(), std::size_t(surface.atlas().topology().patch_count) + 1);
    const PaintedSurface before = shown;
    scatter(surface.painted_vertices(changes.patches), shown);
    const PaintedSurface full = surface.painted_surface();
    if (shared) {
      ASSERT_EQ(surface.display_arrays(), shared); // brought up to date, the same arrays
      expect_display(*shared, full, before);
    }
    ASSERT_TRUE(same_bits(shown.surface.points, full.surface.points));
    ASSERT_TRUE(same_bits(shown.surface.normals, full.surface.normals));
    ASSERT_TRUE(same_bits(shown.diffuse, full.diffuse));
    ASSERT_TRUE(same_bits(shown.specular, full.specular));
    ASSERT_TRUE(same_bits(shown.roughness, full.roughness));
    ASSERT_TRUE(same_bits(shown.displacement, full.displacement));
    ASSERT_TRUE(same_bits(shown.mask, full.mask));
    ASSERT_TRUE(same_bits(shown.label, full.label));
    ASSERT_TRUE(same_bits(shown.inside_diffuse, full.inside_diffuse));
    ASSERT_TRUE(same_bits(shown.inside_specular, full.inside_specular));
    ASSERT_TRUE(same_bits(shown.inside_roughness, full.inside_roughness));
  }
  EXPECT_EQ(partial, 30) << "no action of a session should need a full read";
  // Nothing changed: nothing to read.
  EXPECT_TRUE(surface.changes_since(surface.change_count()).patches.empty());
  surface.write_channels(surface.read_channels());
  EXPECT_TRUE(surface.changes_since(seen).all);
}

INSTANTIATE_TEST_SUITE_P(Seeds, UndoProperty, testing::Values(1u, 2u, 3u, 4u));

// The shared display arrays catch up with every change made since they were
// last asked for, whoever asked, and follow a surface that turns two-sided.
TEST(DisplayArrays, CatchUpWithChangesMadeWhileNobodyLooked)
{
  PaintSurface surface(test::runtime(), test::genus_two(), kLevel, AtlasStorage::Buffer);
  const std::shared_ptr<DisplayArrays> first = surface.display_arrays();
  if (!first)
    GTEST_SKIP() << "the device's memory is its own";
  const PaintedSurface start = surface.painted_surface();
  StrokeMaker maker(7);
  for (int k = 0; k < 6; ++k)
    surface.apply(parse_one(maker.next()));
  surface.undo();
  const PaintedSurface now = surface.painted_surface();
  ASSERT_EQ(surface.display_arrays(), first);
  expect_display(*first, now, start);
  surface.set_two_sided(true);
  surface.apply(parse_one(maker.next()));
  const std::shared_ptr<DisplayArrays> both = surface.display_arrays();
  ASSERT_EQ(both->arrays().size(), 11u);
  const PaintedSurface two_sided = surface.painted_surface();
  expect_display(*both, two_sided, two_sided);
}

//! Strokes at coarser edit levels keep their details across strokes. These
//! sessions make undo put back details that a later step replaced or moved
//! around (an encoding at another level, a stroke at the finest level, the
//! levels between the edit level and the finest) and then go on editing at
//! the first level: what remains applied, replayed on a fresh surface, must
//! give the same bits.
class KeptDetails : public testing::TestWithParam<const char*>
{
};

TEST_P(KeptDetails, ReplayOfWhatRemainsGivesTheSameBits)
{
  const auto coarse = [](const char* at, int level) {
    return parse_one(std::string("{\"tool\": \"inflate\", \"points\": [") + at +
                     "], \"radius\": 0.9, \"amount\": 0.05, \"edit_level\": " + std::to_string(level) + "}");
  };
  const Stroke fine = parse_one(R"({"tool": "sculpt", "points": [[2.5, 1.5, 1]], "radius": 0.8, "amount": 0.04})");
  PaintSurface surface(test::runtime(), test::genus_two(), kLevel, AtlasStorage::Buffer);
  for (const char* action = GetParam(); *action; ++action) {
    switch (*action) {
    case 'a': surface.apply(coarse("[1.0, 1.5, 1]", 1)); break;
    case 'b': surface.apply(coarse("[1.6, 1.2, 1]", 1)); break;
    case 'c': surface.apply(coarse("[2.0, 1.8, 1]", 2)); break;
    case 'd': surface.apply(coarse("[2.4, 1.0, 1]", 1)); break;
    case 'f': surface.apply(fine); break;
    case 'u': ASSERT_TRUE(surface.undo()); break;
    case 'r': ASSERT_TRUE(surface.redo()); break;
    }
  }
  const AtlasState end = read_state(surface);
  PaintSurface fresh(test::runtime(), test::genus_two(), kLevel, AtlasStorage::Buffer);
  for (const Stroke& s : surface.history())
    fresh.apply(s);
  EXPECT_TRUE(same_bits(read_state(fresh), end)) << GetParam();
}

// a, b, d: edit level 1 in three places, c: level 2, f: finest level,
// u: undo, r: redo.
INSTANTIATE_TEST_SUITE_P(Sessions, KeptDetails,
                         testing::Values("aa", "aba", "abub", "acua", "afua", "afaua", "afauua", "acurua", "afuurra",
                                         "abcuub", "abua", "adua", "adub", "bdua",
                                         "dbua"));

// A long session: many strokes in one run keep the undo log within its
// budget, forgetting the oldest strokes (and saying so), and the surface
// keeps working.
TEST(LongSession, TenThousandStrokesStayWithinTheUndoBudget)
{
  PaintSurface surface(test::runtime(), test::flat_grid(4), 2, AtlasStorage::Buffer);
  Stroke s;
  s.points = {{1.f, 1.f, 0.f}};
  s.brush.radius = 0.6f;
  s.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  s.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  surface.apply(s);
  const std::size_t one = surface.undo_log().bytes();
  ASSERT_GT(one, 0u);
  const std::size_t budget = 50 * one;
  surface.undo_log().set_budget(budget);
  std::size_t forgotten_notes = 0, most = 0;
  long rss_warm = 0;
  for (int k = 0; k < 10000; ++k) {
    if (k == 1000)
      rss_warm = resident_bytes();
    s.points = {{float(k % 4), float((k / 4) % 4), 0.f}};
    s.paint().value[CHANNEL_DIFFUSE] = {float(k % 7) / 7.f, 0.5f, 0.f, 1.f};
    surface.apply(s);
    most = std::max(most, surface.undo_log().bytes());
    forgotten_notes += surface.undo_log().take_messages().size();
  }
  EXPECT_LE(most, budget);
  EXPECT_GT(forgotten_notes, 0u);
  // Beyond the undo log, memory grows only by the recorded strokes
  // (history(), a few hundred bytes each); 64 MiB would be a leak per stroke.
  const long growth = resident_bytes() - rss_warm;
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps freed memory in quarantine (256 MiB by default):
  // resident memory says nothing about leaks there; the log's bound above does.
  (void)growth;
#else
  EXPECT_LT(growth, 64l << 20) << "resident memory grew by " << growth << " bytes over 9000 strokes";
#endif
  EXPECT_EQ(surface.history().size(), 10001u);
  EXPECT_TRUE(surface.undo());
}

} // namespace
} // namespace meshpaint
