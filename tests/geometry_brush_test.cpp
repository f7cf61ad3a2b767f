// Brushes that move geometry: sculpt, inflate, flatten and smoothing, with
// the limit surface kept current on the touched patches.

#include "atlas/weld.h"
#include "atlas/welded_neighbours.h"
#include "paint/paint_device.h"
#include "paint/paint_surface.h"
#include "support/copies.h"
#include "support/runtime.h"
#include "support/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>  // for std::max_element
#include <cmath>      // for std::sqrt, std::sin
#include <cstring>    // for std::memcmp
#include <functional> // for std::function
#include <map>        // for std::map
#include <set>        // for std::multiset, std::set
#include <stdexcept>  // for std::logic_error
#include <string>     // for std::string

namespace meshpaint {
namespace {

double volume(const WeldedSurface& s)
{
  double v = 0;
  const auto tri = [&](int a, int b, int c) {
    const Vec3 &p = s.points[a], &q = s.points[b], &r = s.points[c];
    v += (double(p[0]) * (double(q[1]) * r[2] - double(q[2]) * r[1]) -
          double(p[1]) * (double(q[0]) * r[2] - double(q[2]) * r[0]) +
          double(p[2]) * (double(q[0]) * r[1] - double(q[1]) * r[0])) / 6.0;
  };
  for (const auto& q : s.quads) {
    tri(q[0], q[1], q[2]);
    tri(q[0], q[2], q[3]);
  }
  return v;
}

//! Noise as the root mean square of the umbrella vector (mean of the edge
//! neighbours minus the point) over the welded surface.
double roughness_of(const WeldedSurface& s)
{
  std::vector<std::vector<int>> nbrs(s.points.size());
  for (const auto& q : s.quads)
    for (int k = 0; k < 4; ++k) {
      nbrs[q[k]].push_back(q[(k + 1) % 4]);
      nbrs[q[(k + 1) % 4]].push_back(q[k]);
    }
  double sum2 = 0;
  for (std::size_t v = 0; v < s.points.size(); ++v) {
    double m[3] = {0, 0, 0};
    for (const int w : nbrs[v])
      for (int a = 0; a < 3; ++a)
        m[a] += s.points[w][a] / double(nbrs[v].size());
    for (int a = 0; a < 3; ++a)
      sum2 += (m[a] - s.points[v][a]) * (m[a] - s.points[v][a]);
  }
  return std::sqrt(sum2 / double(s.points.size()));
}

Stroke brush(Tool tool, const Vec3& at, float radius)
{
  Stroke s = make_stroke(tool);
  s.points = {at};
  s.brush.radius = radius;
  s.brush.falloff = FALLOFF_CONSTANT;
  return s;
}

// Smoothing's neighbour tables against the quads of the welded surface:
// every vertex reads its own texel, and its neighbours are the quad mesh's
// edge neighbours (along the border only, for a border vertex; none for the
// corner of a single quad).
TEST(GeometryBrush, WeldedNeighboursAreTheQuadMeshsEdges)
{
  for (const std::string& name : test::shape_names()) {
    Atlas atlas(test::runtime(), test::shape(name), 3, AtlasStorage::Buffer);
    atlas.subdivide(1, 3);
    for (int level = 1; level <= 3; ++level) {
      const LevelLayout l = atlas.layout(level);
      const WeldedNeighbours w = welded_neighbours(atlas.topology(), l);
      const WeldedSurface s = weld(atlas.topology(), l, atlas.read_positions(level), nullptr);
      ASSERT_EQ(w.vertices(), s.points.size()) << name;
      std::map<std::pair<int, int>, int> edges; // quads per edge
      for (const auto& q : s.quads)
        for (int k = 0; k < 4; ++k)
          ++edges[std::minmax(q[std::size_t(k)], q[std::size_t((k + 1) % 4)])];
      std::vector<std::multiset<int>> all(w.vertices()), border(w.vertices());
      std::vector<int> faces(w.vertices(), 0);
      for (const auto& q : s.quads)
        for (const int v : q)
          ++faces[std::size_t(v)];
      for (const auto& [e, quads] : edges) {
        all[std::size_t(e.first)].insert(e.second);
        all[std::size_t(e.second)].insert(e.first);
        if (quads == 1) {
          border[std::size_t(e.first)].insert(e.second);
          border[std::size_t(e.second)].insert(e.first);
        }
      }
      for (std::size_t v = 0; v < w.vertices(); ++v) {
        ASSERT_EQ(w.vertex_of[std::size_t(w.texel[v])], int(v)) << name << " level " << level;
        std::multiset<int> got;
        if (int(v) < w.edge_base)
          got.insert(w.ring.begin() + w.first[v], w.ring.begin() + w.first[v + 1]);
        else
          for (const int n : std::set<int>(w.around[v - std::size_t(w.edge_base)].begin(),
                                           w.around[v - std::size_t(w.edge_base)].end()))
            got.insert(n);
        const std::multiset<int> want =
          border[v].empty() ? all[v] : faces[v] == 1 && int(v) < w.edge_base ? std::multiset<int>() : border[v];
        ASSERT_EQ(got, want) << name << " level " << level << " vertex " << v;
      }
    }
  }
}

// One pass of Laplacian smoothing over a whole surface moves every welded
// vertex to x + lambda (mean - x), the mean of its neighbours as the
// tables give them (in pairs inside and along sides, in ring order at
// corners of every valence), at each level.
TEST(GeometryBrush, ALaplacianPassIsTheUmbrellaOfEachVertex)
{
  for (const std::string& name : test::shape_names()) {
    if (name == "two_components") // the brush floods one component only
      continue;
    for (int level = 1; level <= 3; ++level) {
      PaintSurface surface(test::runtime(), test::shape(name), level, AtlasStorage::Buffer);
      Atlas& atlas = surface.atlas();
      const LevelLayout l = atlas.layout(level);
      const WeldedNeighbours w = welded_neighbours(atlas.topology(), l);
      const WeldedSurface before = weld(atlas.topology(), l, atlas.read_positions(level), nullptr);
      Stroke s = brush(Tool::Smooth, before.points.front(), 1e4f); // the whole surface, weight 1
      s.smooth().taubin = false;
      s.smooth().iterations = 1;
      const float lambda = s.smooth().lambda;
      surface.apply(s);
      const WeldedSurface after = weld(atlas.topology(), l, atlas.read_positions(level), nullptr);
      ASSERT_EQ(after.points.size(), w.vertices()) << name;
      float scale = 0.f;
      for (const Vec3& p : before.points)
        for (const float c : p)
          scale = std::max(scale, std::fabs(c));
      std::map<int, int> valences; // corners checked, by ring size
      for (std::size_t v = 0; v < w.vertices(); ++v) {
        std::vector<int> nbrs;
        if (int(v) < w.edge_base) {
          nbrs.assign(w.ring.begin() + w.first[v], w.ring.begin() + w.first[v + 1]);
          ++valences[int(nbrs.size())];
        } else {
          const auto& a = w.around[v - std::size_t(w.edge_base)];
          nbrs.assign(a.begin(), a.end());
        }
        for (int c = 0; c < 3; ++c) {
          const float x = before.points[v][std::size_t(c)];
          float mean = 0.f;
          for (const int n : nbrs)
            mean += before.points[std::size_t(n)][std::size_t(c)];
          const float want = nbrs.empty() ? x : x + lambda * (mean / float(nbrs.size()) - x);
          ASSERT_NEAR(after.points[v][std::size_t(c)], want, 1e-5f * scale)
            << name << " level " << level << " vertex " << v << " of " << nbrs.size() << " neighbours";
        }
      }
      if (level == 2 && name == "high_valence")
        EXPECT_GE(valences.size(), 3u) << "corners of several valences";
    }
  }
}

TEST(GeometryBrush, SculptMovesTheCentreByAmountAlongTheNormal)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, AtlasStorage::Buffer);
  Stroke s = brush(Tool::Sculpt, {3.f, 3.f, 0.f}, 1.5f);
  s.move().amount = 0.2f;
  surface.apply(s);
  const WeldedSurface out = surface.painted_surface().surface;
  bool found = false;
  for (std::size_t v = 0; v < out.points.size(); ++v)
    if (std::fabs(out.points[v][0] - 3.f) < 1e-6 && std::fabs(out.points[v][1] - 3.f) < 1e-6) {
      EXPECT_NEAR(out.points[v][2], 0.2f, 1e-6);
      EXPECT_NEAR(out.normals[v][2], 1.f, 1e-6);
      found = true;
    }
  EXPECT_TRUE(found);
  // Far from the brush nothing moved.
  for (std::size_t v = 0; v < out.points.size(); ++v)
    if (std::hypot(out.points[v][0] - 3.f, out.points[v][1] - 3.f) > 2.5f)
      ASSERT_EQ(out.points[v][2], 0.f);
}

//! Sculpts a flat grid over (3, 3) with radius 2.5 after `protect` set a
//! mask; returns the height of every welded point.
template <typename Protect>
std::vector<float> heights_after_masked_sculpt(Protect protect)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 3, AtlasStorage::Buffer);
  protect(surface);
  Stroke s = brush(Tool::Sculpt, {3.f, 3.f, 0.f}, 2.5f);
  s.move().amount = 0.2f;
  surface.apply(s);
  const WeldedSurface out = surface.painted_surface().surface;
  std::vector<float> z;
  for (const Vec3& p : out.points)
    z.push_back(std::hypot(p[0] - 2.f, p[1] - 3.f) < 0.5f ? p[2] : -1.f); // only the masked disc's
  return z;
}

TEST(GeometryBrush, AMaskKeepsGeometryInPlace)
{
  Stroke mask = brush(Tool::Paint, {2.f, 3.f, 0.f}, 1.f);
  mask.brush.falloff = FALLOFF_CONSTANT;
  mask.paint().value[CHANNEL_MASK] = {1.f, 1.f, 1.f, 1.f};
  mask.paint().alpha[CHANNEL_MASK] = 1.f;
  // Painted, painted and brought back by undo and redo, and loaded with the
  // channels: every way a mask arrives protects the control points under it
  // (and so their limit, which the welded surface shows).
  const std::map<std::string, std::function<void(PaintSurface&)>> ways = {
    {"painted", [&](PaintSurface& s) { s.apply(mask); }},
    {"redone", [&](PaintSurface& s) {
       s.apply(mask);
       ASSERT_TRUE(s.undo());
       ASSERT_TRUE(s.redo());
     }},
    {"loaded", [&](PaintSurface& s) {
       PaintSurface other(test::runtime(), test::flat_grid(6), 3, AtlasStorage::Buffer);
       other.apply(mask);
       s.write_channels(other.read_channels());
     }}};
  for (const auto& [name, way] : ways) {
    const std::vector<float> z = heights_after_masked_sculpt(way);
    int inside = 0;
    for (const float h : z)
      if (h != -1.f) {
        ++inside;
        EXPECT_EQ(h, 0.f) << name;
      }
    EXPECT_GT(inside, 4) << name;
  }
  // Without a mask the same stroke lifts that disc.
  const std::vector<float> free = heights_after_masked_sculpt([](PaintSurface&) {});
  EXPECT_GT(*std::max_element(free.begin(), free.end()), 0.05f);
}

std::vector<Float4> read_bounds(Atlas& atlas)
{
  std::vector<Float4> out(std::size_t(atlas.topology().patch_count));
  atlas.runtime().queue().enqueueReadBuffer(atlas.limit_bounds(), CL_TRUE, 0, out.size() * sizeof(Float4), out.data());
  return out;
}

TEST(GeometryBrush, LocalLimitUpdateEqualsAFullOne)
{
  // The set to update comes as host lists for a small brush and as flags
  // made on the device for a large one (Atlas::neighbourhood()): both
  // must give the bits of the whole surface's limit, and bounds, under each
  // storage and each form of the whole-tile kernels.
  std::set<bool> large_seen;
  for (const AtlasStorage storage : {AtlasStorage::Buffer, AtlasStorage::Image})
    for (const bool per_patch : {true, false})
      for (const float radius : {0.3f, 0.7f, 1.5f}) {
        const std::string what = std::string(storage == AtlasStorage::Image ? "image" : "buffer") +
                                 (per_patch ? ", per patch" : ", per texel") + ", radius " + std::to_string(radius);
        PaintSurface surface(test::runtime(), test::genus_two(), 4, storage);
        surface.atlas().set_patch_items(per_patch);
        Stroke s = brush(Tool::Inflate, {1.5f, 0.5f, 1.f}, radius);
        s.brush.falloff = FALLOFF_SMOOTHSTEP;
        s.move().amount = 0.1f;
        const StrokeReport r = surface.apply(s);
        const int patches = surface.atlas().topology().patch_count;
        ASSERT_GT(r.patches_touched, 0u) << what;
        ASSERT_LT(r.patches_touched, std::size_t(patches)) << what; // a local update, not everything
        large_seen.insert(surface.atlas().sets_on_device(r.patches_touched));
        const auto local_pos = surface.atlas().read_limit_positions();
        const auto local_nrm = surface.atlas().read_limit_normals();
        const auto local_bounds = read_bounds(surface.atlas());
        surface.atlas().compute_limit();
        const auto full_pos = surface.atlas().read_limit_positions();
        const auto full_nrm = surface.atlas().read_limit_normals();
        const auto full_bounds = read_bounds(surface.atlas());
        EXPECT_EQ(std::memcmp(local_pos.data(), full_pos.data(), full_pos.size() * sizeof(Float4)), 0) << what;
        EXPECT_EQ(std::memcmp(local_nrm.data(), full_nrm.data(), full_nrm.size() * sizeof(Float4)), 0) << what;
        EXPECT_EQ(std::memcmp(local_bounds.data(), full_bounds.data(), full_bounds.size() * sizeof(Float4)), 0)
          << what;
      }
  EXPECT_EQ(large_seen, (std::set<bool>{false, true})) << "both ways of making the set ran";
}

//! A finest-level sculpt and a coarse one (edit level 2), whose rebuild
//! runs subdivision and decoding, then the limit: the finest level and the
//! limit layers after them.
std::vector<std::vector<Float4>> after_fine_and_coarse_sculpts(PaintSurface& surface)
{
  Stroke s = brush(Tool::Sculpt, {1.5f, 0.5f, 1.f}, 0.7f);
  s.brush.falloff = FALLOFF_SMOOTHSTEP;
  s.move().amount = 0.1f;
  surface.apply(s);
  s.set_edit_level(2);
  s.points = {{0.5f, 0.5f, 1.f}};
  surface.apply(s);
  return {surface.atlas().read_positions(4), surface.atlas().read_limit_positions(),
          surface.atlas().read_limit_normals()};
}

TEST(GeometryBrush, PatchItemsAndTexelItemsGiveTheSameBitsForKeptWeights)
{
  // A grab and a smoothing pass at an edit level keep their weights
  // (dab_weights, then move_points or the smoothing): both forms of those.
  std::vector<std::vector<Float4>> results;
  for (const bool per_patch : {true, false}) {
    PaintSurface surface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer);
    surface.atlas().set_patch_items(per_patch);
    Stroke grab = brush(Tool::Grab, {1.5f, 0.5f, 1.f}, 0.7f);
    grab.brush.falloff = FALLOFF_SMOOTHSTEP;
    grab.points.push_back({1.5f, 0.5f, 1.3f});
    grab.set_edit_level(2);
    EXPECT_GT(surface.apply(grab).dabs_applied, 0u);
    Stroke smooth = brush(Tool::Smooth, {0.5f, 0.5f, 1.f}, 0.7f);
    smooth.set_edit_level(2);
    EXPECT_GT(surface.apply(smooth).dabs_applied, 0u);
    results.push_back(surface.atlas().read_positions(2));
    results.push_back(surface.atlas().read_positions(4));
  }
  ASSERT_EQ(results.size(), 4u);
  for (const std::size_t k : {0u, 1u})
    EXPECT_EQ(std::memcmp(results[k].data(), results[k + 2].data(), results[k].size() * sizeof(Float4)), 0)
      << "layer " << k;
  EXPECT_NE(std::memcmp(results[1].data(),
                        PaintSurface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer)
                          .atlas()
                          .read_positions(4)
                          .data(),
                        results[1].size() * sizeof(Float4)),
            0)
    << "the strokes moved nothing";
}

void expect_same_bits(const std::vector<std::vector<Float4>>& a, const std::vector<std::vector<Float4>>& b,
                      const std::string& what)
{
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].size(), b[k].size());
    EXPECT_EQ(std::memcmp(a[k].data(), b[k].data(), a[k].size() * sizeof(Float4)), 0) << what << ", layer " << k;
  }
}

TEST(GeometryBrush, PatchItemsAndTexelItemsGiveTheSameBits)
{
  // The whole-tile kernels' two forms (a work item per patch, per texel).
  std::vector<std::vector<std::vector<Float4>>> results;
  for (const bool per_patch : {true, false}) {
    PaintSurface surface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer);
    surface.atlas().set_patch_items(per_patch);
    results.push_back(after_fine_and_coarse_sculpts(surface));
  }
  expect_same_bits(results[0], results[1], "per patch against per texel");
  EXPECT_NE(std::memcmp(results[0][0].data(), PaintSurface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer)
                                                 .atlas()
                                                 .read_positions(4)
                                                 .data(),
                        results[0][0].size() * sizeof(Float4)),
            0)
    << "the strokes moved nothing";
}

TEST(GeometryBrush, PatchLanesMoveAsTexelItems)
{
  // A plain dab (a ball, no stamp, no mask) moves eight patches per work
  // item where patches are items (move_dab_lanes): each move mode and
  // falloff, at the finest level and at an edit level (whose shared sides
  // and corners are held), under both storages, against the per-texel form.
  struct Case
  {
    Tool tool;
    int falloff;
  };
  for (const AtlasStorage storage : {AtlasStorage::Buffer, AtlasStorage::Image})
    for (const Case c : {Case{Tool::Sculpt, FALLOFF_GAUSSIAN}, Case{Tool::Inflate, FALLOFF_LINEAR},
                         Case{Tool::Flatten, FALLOFF_SMOOTHSTEP}, Case{Tool::Sculpt, FALLOFF_CONSTANT}}) {
      std::vector<std::vector<std::vector<Float4>>> results;
      for (const bool per_patch : {true, false}) {
        PaintSurface surface(test::runtime(), test::genus_two(), 4, storage);
        surface.atlas().set_patch_items(per_patch);
        Stroke s = brush(c.tool, {1.5f, 0.5f, 1.f}, 0.8f);
        s.brush.falloff = c.falloff;
        s.move().amount = 0.1f;
        EXPECT_GT(surface.apply(s).dabs_applied, 0u);
        s.set_edit_level(2);
        s.points = {{0.5f, 0.5f, 1.f}};
        EXPECT_GT(surface.apply(s).dabs_applied, 0u);
        results.push_back({surface.atlas().read_positions(2), surface.atlas().read_positions(4)});
      }
      const std::string what = std::string(storage == AtlasStorage::Image ? "image" : "buffer") + ", tool " +
                               std::to_string(int(c.tool)) + ", falloff " + std::to_string(c.falloff);
      expect_same_bits(results[0], results[1], what);
      PaintSurface untouched(test::runtime(), test::genus_two(), 4, storage);
      EXPECT_NE(std::memcmp(results[0][1].data(), untouched.atlas().read_positions(4).data(),
                            results[0][1].size() * sizeof(Float4)),
                0)
        << what << ": the strokes moved nothing";
    }
}

TEST(GeometryBrush, HostListsAndDeviceFlagsGiveTheSameBits)
{
  // The two ways of making a neighbourhood set (Atlas::device_set_share()),
  // under each storage and each form of the whole-tile kernels: the
  // sculpts (the coarse one's edit-level limit too), and their undo (which
  // subdivides the edit level on a set).
  for (const AtlasStorage storage : {AtlasStorage::Buffer, AtlasStorage::Image})
    for (const bool per_patch : {true, false}) {
      std::vector<std::vector<std::vector<Float4>>> results;
      for (const bool flags : {false, true}) {
        PaintSurface surface(test::runtime(), test::genus_two(), 4, storage);
        surface.atlas().set_patch_items(per_patch);
        surface.atlas().set_device_set_share(flags ? std::size_t(surface.atlas().topology().patch_count) : 0);
        results.push_back(after_fine_and_coarse_sculpts(surface));
        ASSERT_TRUE(surface.undo());
        ASSERT_TRUE(surface.undo());
        results.back().push_back(surface.atlas().read_positions(3));
        results.back().push_back(surface.atlas().read_limit_normals());
      }
      expect_same_bits(results[0], results[1],
                       std::string(storage == AtlasStorage::Image ? "image" : "buffer") +
                         (per_patch ? ", per patch" : ", per texel"));
    }
}

TEST(GeometryBrush, AStaleDeviceSetIsRefused)
{
  // Flags belong to the last set made: an older set's would drop what the
  // two differ in, so taking one throws instead.
  PaintSurface surface(test::runtime(), test::genus_two(), 4, AtlasStorage::Buffer);
  Atlas& atlas = surface.atlas();
  atlas.set_device_set_share(std::size_t(atlas.topology().patch_count)); // flags always
  const PatchSet older = atlas.neighbourhood({0, 1, 2});
  const PatchSet newer = atlas.neighbourhood({3});
  EXPECT_NO_THROW(atlas.update_limit(newer));
  EXPECT_THROW(atlas.update_limit(older), std::logic_error);
  EXPECT_THROW(atlas.subdivide(1, 4, older), std::logic_error);
}

TEST(GeometryBrush, DensePassesSmoothAsListedOnesDo)
{
  // Smoothing over every vertex with the unmoved weighing 0 against passes
  // over a list of the moved (WeldedSmoothing::set_dense_from()), under
  // each storage, on a closed surface and one with a border: small and large
  // brushes (a dense pass then reads vertices no tile of the set gave it),
  // Taubin and Laplacian, colours, and at an edit level.
  for (const AtlasStorage storage : {AtlasStorage::Buffer, AtlasStorage::Image})
    for (const char* name : {"genus two", "open grid"}) {
      const bool closed = std::string(name) == "genus two";
      const BaseMesh mesh = closed ? test::genus_two() : test::open_grid();
      const Vec3 at = closed ? Vec3{0.5f, 0.5f, 1.f} : Vec3{1.5f, 1.5f, 0.4f};
      std::vector<std::vector<Float4>> results[2];
      for (const bool dense : {false, true}) {
        PaintSurface surface(test::runtime(), mesh, 4, storage);
        surface.state().device.smoothing->set_dense_from(dense ? 0. : 2.);
        Stroke dot = brush(Tool::Paint, at, 0.5f);
        dot.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
        dot.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
        surface.apply(dot);
        for (const float radius : {0.4f, 1.2f, 10.f}) {
          Stroke s = brush(Tool::Smooth, at, radius);
          s.brush.falloff = FALLOFF_SMOOTHSTEP;
          s.smooth().iterations = 3;
          s.smooth().taubin = radius < 1.f;
          EXPECT_GT(surface.apply(s).dabs_applied, 0u) << name << " radius " << radius;
        }
        Stroke blur = brush(Tool::Blur, at, 0.8f);
        blur.smooth().target_colour = true;
        blur.smooth().taubin = false;
        surface.apply(blur);
        Stroke coarse = brush(Tool::Smooth, at, 0.7f);
        coarse.set_edit_level(2);
        EXPECT_GT(surface.apply(coarse).dabs_applied, 0u);
        results[dense] = {surface.atlas().read_positions(4), surface.atlas().read_limit_positions(),
                          surface.read_channels().diffuse};
      }
      expect_same_bits(results[0], results[1],
                       std::string(name) + (storage == AtlasStorage::Image ? ", image" : ", buffer"));
      EXPECT_NE(std::memcmp(results[0][0].data(), PaintSurface(test::runtime(), mesh, 4, storage)
                                                     .atlas()
                                                     .read_positions(4)
                                                     .data(),
                            results[0][0].size() * sizeof(Float4)),
                0)
        << name << ": the strokes moved nothing";
    }
}

TEST(GeometryBrush, TaubinSmoothingRemovesNoiseAndKeepsTheVolume)
{
  const BaseMesh sphere = test::noisy_sphere(8, 0.f);
  std::map<bool, double> shrink;
  for (const bool taubin : {true, false}) {
    PaintSurface surface(test::runtime(), sphere, 3, AtlasStorage::Buffer);
    // Noise on the finest control points, the same on every stored copy.
    const LevelLayout layout = surface.atlas().layout(3);
    const std::vector<int> map = weld_map(surface.atlas().topology(), layout);
    std::vector<Float4> control = surface.atlas().read_positions(3);
    for (std::size_t t = 0; t < control.size(); ++t) {
      const float r = 1.f + 0.01f * float(std::sin(12.9898 * map[t] + 78.233));
      for (int a = 0; a < 3; ++a)
        control[t][a] *= r;
    }
    surface.atlas().write_positions(3, control);
    surface.geometry_changed();
    const WeldedSurface before = surface.painted_surface().surface;
    Stroke s = brush(Tool::Smooth, {0.f, 0.f, 1.f}, 10.f); // covers the whole sphere
    s.smooth().iterations = 20;
    s.smooth().taubin = taubin;
    surface.apply(s);
    const WeldedSurface after = surface.painted_surface().surface;
    EXPECT_LT(roughness_of(after), 0.5 * roughness_of(before)) << (taubin ? "taubin" : "laplacian");
    shrink[taubin] = std::fabs(volume(after) / volume(before) - 1.0);
    RecordProperty(std::string(taubin ? "taubin" : "laplacian") + "_noise_after_over_before",
                   std::to_string(roughness_of(after) / roughness_of(before)));
  }
  EXPECT_LT(shrink[true], 0.01) << "Taubin smoothing changed the volume by " << shrink[true];
  EXPECT_GT(shrink[false], shrink[true]) << "Laplacian smoothing should shrink more than Taubin";
}

TEST(GeometryBrush, FlattenPullsTowardsThePlane)
{
  PaintSurface surface(test::runtime(), test::open_grid(), 4, AtlasStorage::Buffer);
  const auto spread = [](const WeldedSurface& w) {
    double lo = 1e9, hi = -1e9;
    for (const Vec3& p : w.points)
      if (std::hypot(p[0] - 1.5f, p[1] - 1.5f) < 0.5f) {
        lo = std::min(lo, double(p[2]));
        hi = std::max(hi, double(p[2]));
      }
    return hi - lo;
  };
  const double before = spread(surface.painted_surface().surface);
  Stroke s = brush(Tool::Flatten, {1.5f, 1.5f, 0.4f}, 1.2f);
  s.move().amount = 1.f;
  for (int k = 0; k < 4; ++k)
    surface.apply(s);
  EXPECT_LT(spread(surface.painted_surface().surface), 0.5 * before);
}

TEST(GeometryBrush, BlurSmoothsColoursOnly)
{
  PaintSurface surface(test::runtime(), test::flat_grid(6), 4, AtlasStorage::Buffer);
  Stroke dot = brush(Tool::Paint, {3.f, 3.f, 0.f}, 0.6f);
  dot.paint().value[CHANNEL_DIFFUSE] = {1.f, 0.f, 0.f, 1.f};
  dot.paint().alpha[CHANNEL_DIFFUSE] = 1.f;
  surface.apply(dot);
  const auto positions = surface.atlas().read_positions(4);
  Stroke blur = brush(Tool::Blur, {3.f, 3.f, 0.f}, 2.f);
  blur.smooth().target_colour = true;
  blur.smooth().taubin = false;
  blur.smooth().iterations = 5;
  surface.apply(blur);
  const PaintChannels ch = surface.read_channels();
  std::size_t partial = 0;
  for (const Float4& c : ch.diffuse)
    partial += c[0] > 0.8f && c[0] < 1.f;
  EXPECT_GT(partial, 20u) << "blurring a hard-edged dot leaves intermediate shades";
  const auto after = surface.atlas().read_positions(4);
  EXPECT_EQ(std::memcmp(after.data(), positions.data(), after.size() * sizeof(Float4)), 0);
}

TEST(GeometryBrush, UndoRestoresGeometryBitForBit)
{
  PaintSurface surface(test::runtime(), test::mixed_polygons(), 4, AtlasStorage::Buffer);
  const auto control = surface.atlas().read_positions(4);
  const auto limit = surface.atlas().read_limit_positions();
  Stroke s = brush(Tool::Smooth, {1.f, 0.f, 0.6f}, 0.8f);
  s.brush.falloff = FALLOFF_GAUSSIAN;
  s.smooth().iterations = 3;
  surface.apply(s);
  Stroke t = brush(Tool::Sculpt, {0.f, 1.f, 0.6f}, 0.8f);
  t.move().amount = -0.1f;
  surface.apply(t);
  ASSERT_NE(std::memcmp(surface.atlas().read_positions(4).data(), control.data(), control.size() * sizeof(Float4)), 0);
  while (surface.undo()) {
  }
  EXPECT_EQ(std::memcmp(surface.atlas().read_positions(4).data(), control.data(), control.size() * sizeof(Float4)), 0);
  EXPECT_EQ(std::memcmp(surface.atlas().read_limit_positions().data(), limit.data(), limit.size() * sizeof(Float4)), 0);
}

class GeometryStorage : public testing::TestWithParam<std::string>
{
};

// Smoothing keeps every stored copy identical, and the image path gives the
// same bits as the buffer path.
TEST_P(GeometryStorage, SmoothingIsConsistent)
{
  const BaseMesh mesh = test::shape(GetParam());
  std::vector<std::vector<Float4>> results;
  for (const AtlasStorage storage : {AtlasStorage::Buffer, AtlasStorage::Image}) {
    if (storage == AtlasStorage::Image && !test::runtime()->info().images)
      continue;
    PaintSurface surface(test::runtime(), mesh, 3, storage);
    Stroke s = brush(Tool::Smooth, mesh.points.front(), 0.6f * float(mesh.diagonal()));
    s.brush.falloff = FALLOFF_SMOOTHSTEP;
    s.smooth().iterations = 2;
    surface.apply(s);
    Stroke t = brush(Tool::Inflate, mesh.points.back(), 0.4f * float(mesh.diagonal()));
    t.move().amount = 0.05f;
    surface.apply(t);
    results.push_back(surface.atlas().read_positions(3));
    EXPECT_EQ(test::differing_copies(surface.atlas().topology(), surface.atlas().layout(3), results.back()), 0u);
  }
  if (results.size() == 2)
    EXPECT_EQ(std::memcmp(results[0].data(), results[1].data(), results[0].size() * sizeof(Float4)), 0);
}

INSTANTIATE_TEST_SUITE_P(Shapes, GeometryStorage, testing::ValuesIn(test::shape_names()));

} // namespace
} // namespace meshpaint
