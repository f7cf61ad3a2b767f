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

INSTANTIATE_TEST_SUITE_P(Seeds, UndoProperty, testing::Values(1u, 2u, 3u, 4u));

// A long session: many strokes in one run keep the undo log within its
// budget, forgetting the oldest strokes (and saying so), and the surface
// keeps working.
TEST(LongSession, TenThousandStrokesStayWithinTheUndoBudget)
{
  PaintSurface surface(test::runtime(), test::flat_grid(4), 2, AtlasStorage::Buffer);
  Stroke s;
  s.points = {{1.f, 1.f, 0.f}};
  s.radius = 0.6f;
  s.value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  s.alpha[CHANNEL_DIFFUSE] = 1.f;
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
    s.value[CHANNEL_DIFFUSE] = {float(k % 7) / 7.f, 0.5f, 0.f, 1.f};
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
