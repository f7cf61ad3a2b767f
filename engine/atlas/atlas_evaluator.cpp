#include "atlas/atlas_evaluator.h"

#include "atlas/memory_plan.h"
#include "atlas/tile_ranges.h"
#include "cl/kernel_programs.h"
#include "cl/launch.h"

#include <algorithm> // for std::max
#include <stdexcept> // for std::logic_error

namespace meshpaint {
namespace {

// Work-group size of the table-driven kernels: runs of edges or rings.
constexpr std::size_t kGroup1D = 64;
const cl::NDRange kLocalEdges(1, kGroup1D), kLocal1D(kGroup1D);

cl::NDRange range_edges(int positions, int edges)
{
  return cl::NDRange(positions, round_up(edges, kGroup1D));
}
cl::NDRange range1d(int items) { return cl::NDRange(round_up(items, kGroup1D)); }

} // namespace

//! A PatchSet as the kernels take it: lists and their lengths; or null
//! lists and the full counts, with flags (Form::Flags) or without (every
//! item).
struct AtlasEvaluator::Arguments
{
  cl::Buffer patches, edges, rings;
  int patch_count = 0, edge_count = 0, ring_count = 0;
  cl::Buffer patch_flags, edge_flags, ring_flags;
  cl_int generation = 0;
};

AtlasEvaluator::AtlasEvaluator(Runtime& runtime, const AtlasTables& tables, AtlasStorage storage,
                               const LevelLayout& finest)
  : runtime_(runtime), tables_(tables), storage_(storage), patch_items_(patch_items_on(runtime.info()))
{
  const cl::Program& program = kernel_program(runtime_, KernelProgram::Atlas, storage_options(storage, runtime_.info()));
  subdivide_tiles_ = cl::Kernel(program, "subdivide_tiles");
  subdivide_patches_ = cl::Kernel(program, "subdivide_patches");
  subdivide_edges_ = cl::Kernel(program, "subdivide_edges");
  subdivide_corners_ = cl::Kernel(program, "subdivide_corners");
  subdivide_corner_levels_ = cl::Kernel(program, "subdivide_corner_levels");
  subdivide_first_step_ = cl::Kernel(program, "subdivide_first_step");
  subdivide_second_step_ = cl::Kernel(program, "subdivide_second_step");
  limit_tiles_ = cl::Kernel(program, "limit_tiles");
  limit_patches_ = cl::Kernel(program, "limit_patches");
  limit_edges_ = cl::Kernel(program, "limit_edges");
  limit_corners_ = cl::Kernel(program, "limit_corners");
  patch_bounds_ = cl::Kernel(program, "patch_bounds");
  cluster_bounds_ = cl::Kernel(program, "cluster_bounds");
  flag_corners_ = cl::Kernel(program, "flag_corners");
  flag_ring_patches_ = cl::Kernel(program, "flag_ring_patches");
  flag_borders_ = cl::Kernel(program, "flag_borders");
  reduce_interior_ = cl::Kernel(program, "reduce_interior");
  reduce_edges_ = cl::Kernel(program, "reduce_edges");
  reduce_edge_walks_ = cl::Kernel(program, "reduce_edge_walks");
  reduce_patches_ = cl::Kernel(program, "reduce_patches");
  reduce_corners_ = cl::Kernel(program, "reduce_corners");
  reduce_second_step_ = cl::Kernel(program, "reduce_second_step");
  reduce_sectors_ = cl::Kernel(program, "reduce_sectors");

  const AtlasTopology& topo = tables_.topology();
  const cl::Context& context = runtime_.context();
  side_work_ = cl::Buffer(context, CL_MEM_READ_WRITE,
                          std::max<std::size_t>(1, topo.edges.size() * std::size_t(finest.n - 1)) * 2 *
                              sizeof(cl_float4));
  corner_layers_ = int(corner_work_layers(finest.level));
  corner_work_ = cl::Buffer(context, CL_MEM_READ_WRITE,
                            std::max<std::size_t>(1, topo.rings.size() * std::size_t(corner_layers_)) *
                                sizeof(cl_float4));
  ring_marks_ = cl::Buffer(context, CL_MEM_READ_WRITE, std::max<std::size_t>(1, topo.rings.size()));
  wide_rings_ = std::any_of(topo.rings.begin(), topo.rings.end(),
                            [](const CornerRing& r) { return !r.boundary && r.count > RING_LEVELS_MAX; });
  const auto flags = [&](std::size_t n) {
    const std::size_t bytes = round_up(std::max<std::size_t>(1, n), sizeof(cl_uint)); // whole fill patterns
    cl::Buffer b(context, CL_MEM_READ_WRITE, bytes);
    runtime_.queue().enqueueFillBuffer(b, cl_uint(0), 0, bytes);
    return b;
  };
  patch_flags_ = flags(std::size_t(topo.patch_count));
  edge_flags_ = flags(topo.edges.size());
  ring_flags_ = flags(topo.rings.size());
}

TileLaunch texel_launch(cl::Kernel& per_texel, const LevelLayout& l, int count)
{
  const auto tiles = range_tiles(l, count);
  return {per_texel, tiles.first, tiles.second};
}

TileLaunch AtlasEvaluator::tile_launch(cl::Kernel& per_texel, cl::Kernel& per_patch, const LevelLayout& l,
                                       int count, int patches_per_item) const
{
  if (patch_items_)
    return {per_patch, range1d((count + patches_per_item - 1) / patches_per_item), kLocal1D};
  return texel_launch(per_texel, l, count);
}

AtlasEvaluator::Arguments AtlasEvaluator::arguments(const PatchSet& set) const
{
  Arguments a;
  const AtlasTopology& topo = tables_.topology();
  if (set.form == PatchSet::Form::Lists) {
    const cl::Context& context = runtime_.context();
    a.patches = set.patch_list() ? set.patch_list : device_ints(context, set.patches);
    a.edges = set.edge_list() ? set.edge_list : device_ints(context, set.edges);
    a.rings = set.ring_list() ? set.ring_list : device_ints(context, set.rings);
    a.patch_count = int(set.patches.size());
    a.edge_count = int(set.edges.size());
    a.ring_count = int(set.rings.size());
    return a;
  }
  a.patch_count = topo.patch_count;
  a.edge_count = int(topo.edges.size());
  a.ring_count = int(topo.rings.size());
  if (set.form == PatchSet::Form::Flags) {
    // Flags of an older set have been overwritten where the sets differ.
    if (set.generation != generation_)
      throw std::logic_error("a device-made set used after a newer one was made");
    a.patch_flags = set.patch_flags;
    a.edge_flags = set.edge_flags;
    a.ring_flags = set.ring_flags;
    a.generation = set.generation;
  }
  return a;
}

int AtlasEvaluator::subdivide(int from_level, const std::vector<cl::Memory>& layers, const PatchSet& set,
                              bool last_tiles)
{
  const Arguments a = arguments(set);
  cl::CommandQueue& q = runtime_.queue();
  const int patch_count = tables_.topology().patch_count, steps = int(layers.size()) - 1;
  const cl_int stride = cl_int(tables_.topology().rings.size());
  // One gather of the source level's rings gives the corners of every step;
  // the rings it marks are taken again from each level.
  const bool corner_levels = corners_in_one_pass() && steps > 1 && steps <= corner_layers_ && a.ring_count > 0;
  const cl_uchar mark = 1;
  cl_int corner_base = 0;
  for (int k = 0; k < steps; ++k) {
    const int l = from_level + k;
    const LevelLayout s = level_layout(patch_count, l), d = level_layout(patch_count, l + 1);
    const cl::Memory &in = layers[k], &out = layers[k + 1];
    corner_base = corner_levels ? k * stride : 0;
    // Small tiles on CPUs: a kernel per step that walks each tile's own
    // sides, no side kernel.
    cl::Kernel* small_step = !tiles_walk_sides(l) ? nullptr : l == 1 ? &subdivide_first_step_ : &subdivide_second_step_;
    const bool tiles = last_tiles || k + 1 < steps; // else the caller makes them from the corners
    if (a.edge_count > 0 && !small_step && tiles)
      launch(q, subdivide_edges_, range1d(a.edge_count), kLocal1D, in, side_work_, tables_.edges(), a.edges,
             a.edge_count, a.edge_flags, a.generation, grid(s), grid(d));
    // After the side kernel, which leaves the source level in the caches.
    if (corner_levels && k == 0)
      launch(q, subdivide_corner_levels_, range1d(a.ring_count), kLocal1D, in, corner_work_, cl_int(0), stride,
             cl_int(steps), ring_marks_, mark, tables_.rings(), tables_.slots(), a.rings, a.ring_count,
             a.ring_flags, a.generation, grid(s));
    else if (!corner_levels && a.ring_count > 0)
      launch(q, subdivide_corners_, range1d(a.ring_count), kLocal1D, in, corner_work_, corner_base, tables_.rings(),
             tables_.slots(), a.rings, a.ring_count, a.ring_flags, a.generation, grid(s));
    else if (corner_levels && wide_rings_)
      launch(q, subdivide_corners_, range1d(a.ring_count), kLocal1D, in, corner_work_, corner_base, tables_.rings(),
             tables_.slots(), a.rings, a.ring_count, ring_marks_, cl_int(mark), grid(s));
    if (!tiles)
      break;
    if (a.patch_count > 0 && small_step)
      launch(q, *small_step, range1d(a.patch_count), kLocal1D, in, out, grid(s), grid(d), a.patches, a.patch_count,
             a.patch_flags, a.generation, tables_.patch_rings(), tables_.patch_across(), corner_work_, corner_base);
    else if (a.patch_count > 0) {
      const TileLaunch t = tile_launch(subdivide_tiles_, subdivide_patches_, d, a.patch_count);
      launch(q, t.kernel, t.global, t.local, in, out, grid(s), grid(d), a.patches, a.patch_count, a.patch_flags,
             a.generation, tables_.patch_sides(), tables_.patch_rings(), side_work_, corner_work_, corner_base);
    }
  }
  // No wait: a list released here lives on until the kernels using it end,
  // and the host goes on with its next sets while they run.
  return corner_base;
}

void AtlasEvaluator::reduce(int from, int to, const std::vector<cl::Memory>& levels)
{
  const AtlasTopology& topo = tables_.topology();
  cl::CommandQueue& q = runtime_.queue();
  const int edges = int(topo.edges.size()), rings = int(topo.rings.size()), patches = topo.patch_count;
  bool sectors_left = false; // by this call's step into level 2, for the step into level 1
  for (int level = from; level > to; --level) {
    const cl::Memory &in = levels[std::size_t(level - 1)], &out = levels[std::size_t(level - 2)];
    const LevelLayout s = level_layout(patches, level), d = level_layout(patches, level - 1);
    if (!patch_items_) {
      if (d.n > 1) {
        const auto inside = range_interiors(d, d.patches);
        launch(q, reduce_interior_, inside.first, inside.second, in, out, grid(s), grid(d), patches);
        launch(q, reduce_edges_, range_edges(d.n - 1, edges), kLocalEdges, in, out, tables_.edges(), edges,
               grid(s), grid(d));
      }
      launch(q, reduce_corners_, range1d(rings), kLocal1D, in, out, tables_.rings(), tables_.slots(), rings,
             grid(s), grid(d), cl::Buffer(), cl::Buffer(), cl_int(0));
      continue;
    }
    // Sides and corners into the compact arrays, then whole tiles. Into
    // level 1 the rings sum each patch's sector of them in the order of
    // their slots (the side array is free there): left by the step into
    // level 2 when this call took it, with level 2's corners in the corner
    // array, else from level 2's tiles.
    const bool second_step = d.n == 2, into_first = d.n == 1;
    if (d.n > 2)
      launch(q, reduce_edge_walks_, range1d(edges), kLocal1D, in, side_work_, tables_.edges(), edges, grid(s),
             grid(d));
    if (into_first && !sectors_left)
      launch(q, reduce_sectors_, range1d(patches), kLocal1D, in, grid(s), patches, tables_.patch_slots(),
             side_work_);
    launch(q, reduce_corners_, range1d(rings), kLocal1D, in, out, tables_.rings(), tables_.slots(), rings, grid(s),
           grid(d), corner_work_, into_first ? side_work_ : cl::Buffer(), cl_int(into_first && sectors_left));
    if (second_step) {
      sectors_left = to == 1;
      launch(q, reduce_second_step_, range1d(patches), kLocal1D, in, out, grid(s), grid(d), patches,
             tables_.patch_sides(), tables_.patch_rings(), tables_.patch_across(), tables_.edges(), corner_work_,
             tables_.patch_slots(), sectors_left ? side_work_ : cl::Buffer());
    } else
      launch(q, reduce_patches_, range1d(patches), kLocal1D, in, out, grid(s), grid(d), patches,
             tables_.patch_sides(), tables_.patch_rings(), side_work_, corner_work_);
  }
}

void AtlasEvaluator::limit(int level, const cl::Memory& in, const cl::Memory& pos, const cl::Memory& nrm,
                           const PatchSet& set, const cl::Buffer* bounds)
{
  const Arguments a = arguments(set);
  const LevelLayout l = level_layout(tables_.topology().patch_count, level);
  cl::CommandQueue& q = runtime_.queue();
  if (l.n > 1 && a.edge_count > 0)
    launch(q, limit_edges_, range1d(a.edge_count), kLocal1D, in, side_work_, tables_.edges(), a.edges,
           a.edge_count, a.edge_flags, a.generation, grid(l));
  if (a.ring_count > 0)
    launch(q, limit_corners_, range1d(a.ring_count), kLocal1D, in, corner_work_, tables_.rings(), tables_.slots(),
           tables_.valences(), a.rings, a.ring_count, a.ring_flags, a.generation, grid(l));
  if (a.patch_count > 0) {
    const TileLaunch t = tile_launch(limit_tiles_, limit_patches_, l, a.patch_count);
    // The per-patch kernel makes the bounds as it goes where it may read
    // back what it wrote (buffers); otherwise a kernel of their own.
    const bool fused = bounds && patch_items_ && storage_ == AtlasStorage::Buffer;
    if (patch_items_)
      limit_patches_.setArg(12, fused ? *bounds : cl::Buffer()); // its last, beyond limit_tiles' own
    launch(q, t.kernel, t.global, t.local, in, pos, nrm, grid(l), a.patches, a.patch_count, a.patch_flags,
           a.generation, tables_.patch_sides(), tables_.patch_rings(), side_work_, corner_work_);
    if (bounds && !fused)
      launch(q, patch_bounds_, range1d(a.patch_count), kLocal1D, pos, grid(l), a.patches, a.patch_count,
             a.patch_flags, a.generation, *bounds);
  }
}

void AtlasEvaluator::cluster_bounds(const cl::Buffer& bounds, const cl::Buffer& clusters, const PatchSet& set)
{
  const int patches = tables_.topology().patch_count;
  // Only a flagged set's arguments: a listed one's own lists would be
  // uploaded for nothing, since the kernel takes its clusters instead.
  const Arguments a = set.form == PatchSet::Form::Flags ? arguments(set) : Arguments();
  std::vector<int> touched; // a list's clusters, in order: its patches are sorted
  const bool listed = set.form == PatchSet::Form::Lists;
  if (listed)
    for (const int p : set.patches)
      if (touched.empty() || touched.back() != p / PATCH_CLUSTER)
        touched.push_back(p / PATCH_CLUSTER);
  const int count = listed ? int(touched.size()) : cluster_count(patches);
  if (count == 0)
    return;
  launch(runtime_.queue(), cluster_bounds_, range1d(count), kLocal1D, bounds, patches,
         listed ? device_ints(runtime_.context(), touched) : cl::Buffer(), count, a.patch_flags, a.generation,
         clusters);
}

PatchSet AtlasEvaluator::flag_neighbourhood(const std::vector<int>& changed, const cl::Buffer* list)
{
  const AtlasTopology& topo = tables_.topology();
  cl::CommandQueue& q = runtime_.queue();
  if (++generation_ == 0) { // a flag may still hold any other generation
    for (const cl::Buffer* b : {&patch_flags_, &edge_flags_, &ring_flags_})
      q.enqueueFillBuffer(*b, cl_uint(0), 0, b->getInfo<CL_MEM_SIZE>());
    generation_ = 1;
  }
  const cl_int generation = generation_, count = cl_int(changed.size()), patches = topo.patch_count,
               rings = cl_int(topo.rings.size());
  const cl::Buffer uploaded = list ? cl::Buffer() : device_ints(runtime_.context(), changed);
  // The changed patches' corners, the patches there, and their sides and
  // corners: a subset of the last, so the ring flags serve both.
  launch(q, flag_corners_, range1d(count), kLocal1D, list ? *list : uploaded, count, tables_.patch_rings(),
         generation, ring_flags_);
  launch(q, flag_ring_patches_, range1d(rings), kLocal1D, ring_flags_, rings, tables_.rings(), tables_.slots(),
         generation, patch_flags_);
  launch(q, flag_borders_, range1d(patches), kLocal1D, patch_flags_, patches, tables_.patch_sides(),
         tables_.patch_rings(), generation, edge_flags_, ring_flags_);
  PatchSet flagged;
  flagged.form = PatchSet::Form::Flags;
  flagged.patch_flags = patch_flags_;
  flagged.edge_flags = edge_flags_;
  flagged.ring_flags = ring_flags_;
  flagged.generation = generation;
  return flagged;
}

} // namespace meshpaint
