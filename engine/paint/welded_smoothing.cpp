#include "paint/welded_smoothing.h"

#include "cl/launch.h"
#include "cl/runtime.h"

#include <utility> // for std::move, std::swap

namespace meshpaint {

namespace {

constexpr std::size_t kGroup = 256;

} // namespace

WeldedSmoothing::WeldedSmoothing(Runtime& runtime, const AtlasTopology& topology, const cl::Program& program)
  : runtime_(runtime), topology_(topology), smooth_(program, "welded_smooth"),
    listed_weights_(program, "welded_listed_weights")
{
}

std::size_t WeldedSmoothing::bytes(std::size_t texels, std::size_t vertices)
{
  // Two arrays of values and one of weights, the texel map, and per vertex
  // its texel and four neighbours (a corner's ring takes about as much).
  return 2 * vertices * sizeof(Float4) + texels * sizeof(int) + 6 * vertices * sizeof(int);
}

WeldedSmoothing::Level& WeldedSmoothing::level(const LevelLayout& l)
{
  auto found = levels_.find(l.level);
  if (found != levels_.end())
    return found->second;
  Level w; // kept only once every buffer is made
  WeldedNeighbours host = welded_neighbours(topology_, l);
  const cl::Context& c = runtime_.context();
  w.vertex_of = device_ints(c, host.vertex_of);
  w.texel = device_ints(c, host.texel);
  w.first = device_ints(c, host.first);
  w.ring = device_ints(c, host.ring);
  w.around = device_copy(c, host.around); // empty at level 1: corners only
  w.vertices = host.vertices();
  w.numbering = static_cast<const WeldedNumbering&>(host); // the tables live on the device only
  const std::size_t need = w.vertices * sizeof(Float4);
  if (need > capacity_) {
    a_ = cl::Buffer(c, CL_MEM_READ_WRITE, need);
    b_ = cl::Buffer(c, CL_MEM_READ_WRITE, need);
    weights_ = cl::Buffer(c, CL_MEM_READ_WRITE, w.vertices * sizeof(float));
    capacity_ = need;
  }
  return levels_.emplace(l.level, std::move(w)).first->second;
}

const cl::Buffer& WeldedSmoothing::passes(const LayerKernels& k, const cl::Memory& layer, const LevelLayout& l,
                                          const PatchSet* set, const cl::Buffer& list, const cl::Buffer& weights,
                                          const std::vector<float>& steps)
{
  Level& w = level(l);
  cl::CommandQueue& q = runtime_.queue();
  // Null lists: every patch, every vertex.
  const int count = set ? int(set->patches.size()) : l.patches;
  // The moved vertices: corners first, then the others.
  int corners = set ? int(set->corners.size()) : w.numbering.edge_base;
  int others = set ? int(w.numbering.moved_count(set->patches.size(), set->edges.size(), 0))
                   : int(w.vertices) - w.numbering.edge_base;
  cl::Buffer moved =
    set ? device_ints(runtime_.context(), w.numbering.moved(set->patches, set->edges, set->corners)) : cl::Buffer();
  // A set that moves most of the vertices passes over all of them, the
  // others weighing 0: a pass then reads no list, which made an item on a
  // list cost 1.2-1.6 times as much. Vertices outside the gathered tiles
  // hold stale values, which no moved vertex reads and none is scattered.
  const bool dense = set && corners + others > 0 && double(corners + others) >= dense_from_ * double(w.vertices);
  const auto tiles = range_tiles(l, count);
  cl::Kernel gather = k.gather;
  launch(q, gather, tiles.first, tiles.second, layer, grid(l), list, count, w.vertex_of, w.texel,
         dense ? cl::Buffer() : weights, a_, b_, weights_);
  if (dense) {
    q.enqueueFillBuffer(weights_, 0.f, 0, w.vertices * sizeof(float));
    const int listed = corners + others;
    launch(q, listed_weights_, cl::NDRange(round_up(std::size_t(listed), kGroup)), cl::NDRange(kGroup), moved, listed,
           w.texel, weights, weights_);
    corners = w.numbering.edge_base;
    others = int(w.vertices) - w.numbering.edge_base;
    moved = cl::Buffer();
  }
  const cl::Buffer* from = &a_;
  const cl::Buffer* to = &b_;
  const std::size_t corner_groups = (std::size_t(corners) + kGroup - 1) / kGroup;
  const std::size_t items = kGroup * corner_groups + round_up(std::size_t(others), kGroup);
  for (const float step : steps) {
    if (items > 0)
      launch(q, smooth_, cl::NDRange(items), cl::NDRange(kGroup), *from, *to, moved, corners, others,
             cl_int(corner_groups), w.numbering.edge_base, w.first, w.ring, w.around, weights_, step);
    std::swap(from, to);
  }
  return *from;
}

void WeldedSmoothing::run(const LayerKernels& k, const cl::Memory& layer, const LevelLayout& l, const PatchSet& all_or_lists,
                          const cl::Buffer& weights, const std::vector<float>& steps)
{
  const PatchSet* set = all_or_lists.form == PatchSet::Form::Lists ? &all_or_lists : nullptr; // null: every patch
  if (set && set->patches.empty())
    return;
  const cl::Buffer list = set ? device_ints(runtime_.context(), set->patches) : cl::Buffer();
  const cl::Buffer& result = passes(k, layer, l, set, list, weights, steps);
  const int count = set ? int(set->patches.size()) : l.patches;
  const auto tiles = range_tiles(l, count);
  cl::Kernel scatter = k.scatter;
  launch(runtime_.queue(), scatter, tiles.first, tiles.second, result, layer, grid(l), list, count,
         level(l).vertex_of);
}

std::vector<Float4> WeldedSmoothing::run_welded(const LayerKernels& k, const cl::Memory& layer,
                                                const LevelLayout& l, const cl::Buffer& weights,
                                                const std::vector<float>& steps)
{
  const cl::Buffer& result = passes(k, layer, l, nullptr, cl::Buffer(), weights, steps);
  std::vector<Float4> out(level(l).vertices);
  runtime_.queue().enqueueReadBuffer(result, CL_TRUE, 0, out.size() * sizeof(Float4), out.data());
  return out;
}

} // namespace meshpaint
