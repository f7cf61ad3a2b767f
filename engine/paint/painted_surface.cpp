// The painted surface as the host reads it: all of it (painted_surface), or
// only the vertices of some patches, and which patches changed since a
// display last read it.

#include "paint/paint_surface.h"
#include "paint/snapshots.h"

#include "atlas/weld.h"
#include "cl/launch.h"
#include "cl/kernel_programs.h"
#include "cl/opencl.h"
#include "core/errors.h"

#include <algorithm> // for std::sort

namespace meshpaint {
namespace {

//! Writes the channels of texel `t` into vertex slot `v` of `out`, whose
//! arrays are sized already (the inside's only on two-sided surfaces).
void put_channels(PaintedSurface& out, std::size_t v, const PaintChannels& c, std::size_t t)
{
  out.diffuse[v] = {c.diffuse[t][0], c.diffuse[t][1], c.diffuse[t][2]};
  out.specular[v] = {c.specular[t][0], c.specular[t][1], c.specular[t][2]};
  out.roughness[v] = c.material[t][0];
  out.displacement[v] = c.material[t][1];
  out.label[v] = int(c.material[t][2]);
  out.mask[v] = c.material[t][3];
  if (c.inside_diffuse.empty())
    return;
  out.inside_diffuse[v] = {c.inside_diffuse[t][0], c.inside_diffuse[t][1], c.inside_diffuse[t][2]};
  out.inside_specular[v] = {c.inside_specular[t][0], c.inside_specular[t][1], c.inside_specular[t][2]};
  out.inside_roughness[v] = c.inside_material[t][0];
}

//! Sizes the channel arrays of `out` for `count` vertices.
void size_channels(PaintedSurface& out, std::size_t count, bool inside)
{
  out.diffuse.resize(count);
  out.specular.resize(count);
  out.roughness.resize(count);
  out.displacement.resize(count);
  out.mask.resize(count);
  out.label.resize(count);
  if (inside) {
    out.inside_diffuse.resize(count);
    out.inside_specular.resize(count);
    out.inside_roughness.resize(count);
  }
}

//! The displacement applied along the normal: P = P0 + h N.
void displace(PaintedSurface& out)
{
  for (std::size_t v = 0; v < out.surface.points.size(); ++v)
    for (int k = 0; k < 3; ++k)
      out.surface.points[v][k] += out.displacement[v] * out.surface.normals[v][k];
}

//! Channels per welded vertex, displaced.
PaintedSurface painted(WeldedSurface surface, const std::vector<int>& map, const PaintChannels& c)
{
  PaintedSurface out;
  out.surface = std::move(surface);
  size_channels(out, out.surface.points.size(), !c.inside_diffuse.empty());
  for (std::size_t t = 0; t < map.size(); ++t)
    put_channels(out, std::size_t(map[t]), c, t);
  displace(out);
  return out;
}

} // namespace

PaintedSurface PaintSurface::painted_surface()
{
  return painted(level_surface(*atlas_, level_, true), texel_vertices(state()), read_channels());
}

PaintedSurface PaintSurface::painted_surface(int level)
{
  if (level == level_)
    return painted_surface();
  if (level < 1 || level > level_)
    throw InputError("no level of detail " + std::to_string(level) + ": the surface has levels 1.." +
                     std::to_string(level_));
  // Reducing rewrites the levels below the finest, which hold the base of
  // a coarse edit: its details are made again on the next one.
  atlas_->reduce(level_, level);
  if (multires_)
    multires_->invalidate();
  const LevelLayout c = atlas_->layout(level), f = atlas_->layout(level_);
  const int stride = f.n / c.n;
  const std::vector<Float4> positions = atlas_->read_positions(level), normals = atlas_->read_limit_normals();
  const PaintChannels fine = read_channels();
  std::vector<Float4> coarse_normals(c.texels());
  PaintChannels coarse;
  const auto sampled = [&](const std::vector<Float4>& from, std::vector<Float4>& to) {
    if (from.empty())
      return;
    to.resize(c.texels());
    for (int p = 0; p < c.patches; ++p)
      for (int j = 0; j < c.tile; ++j)
        for (int i = 0; i < c.tile; ++i)
          to[c.index(p, i, j)] = from[f.index(p, i * stride, j * stride)];
  };
  sampled(normals, coarse_normals);
  sampled(fine.diffuse, coarse.diffuse);
  sampled(fine.specular, coarse.specular);
  sampled(fine.material, coarse.material);
  sampled(fine.inside_diffuse, coarse.inside_diffuse);
  sampled(fine.inside_specular, coarse.inside_specular);
  sampled(fine.inside_material, coarse.inside_material);
  return painted(weld(atlas_->topology(), c, positions, &coarse_normals), weld_map(atlas_->topology(), c), coarse);
}

PaintedVertices PaintSurface::painted_vertices(const std::vector<int>& patches)
{
  PaintedVertices out;
  if (patches.empty())
    return out;
  const LevelLayout l = atlas_->layout(level_);
  const std::vector<int>& map = texel_vertices(state());
  // The listed tiles of each layer, gathered on the device and read back:
  // tile after tile, as `patches` lists them.
  const std::size_t per_tile = std::size_t(l.tile) * l.tile;
  std::vector<int> layers{kLimitPositions, kLimitNormals, kDiffuse, kSpecular, kMaterial};
  if (two_sided_)
    layers.insert(layers.end(), {kInsideDiffuse, kInsideSpecular, kInsideMaterial});
  Snapshot tiles;
  try {
    tiles = take_snapshot(state(), patches, layers);
  } catch (const cl::Error& e) {
    throw DeviceError("reading the painted surface failed on " + atlas_->runtime().info().name + ": " +
                      describe(e));
  }
  const std::vector<Float4>& positions = tiles.layers[0];
  const std::vector<Float4>& normals = tiles.layers[1];
  PaintChannels c;
  c.diffuse = std::move(tiles.layers[2]);
  c.specular = std::move(tiles.layers[3]);
  c.material = std::move(tiles.layers[4]);
  if (two_sided_) {
    c.inside_diffuse = std::move(tiles.layers[5]);
    c.inside_specular = std::move(tiles.layers[6]);
    c.inside_material = std::move(tiles.layers[7]);
  }
  // Shared texels are stored in every patch at them, bit-identical: each
  // welded vertex is taken once, from its first copy in the list.
  const std::size_t vertices = atlas_->topology().unique_vertices(level_);
  std::vector<char> seen(vertices, 0);
  PaintedSurface& v = out.values;
  std::vector<std::size_t> from; // gathered texel of each vertex taken
  for (std::size_t k = 0; k < patches.size(); ++k)
    for (int j = 0; j < l.tile; ++j)
      for (int i = 0; i < l.tile; ++i) {
        const int id = map[l.index(patches[k], i, j)];
        if (id < 0 || seen[std::size_t(id)])
          continue;
        seen[std::size_t(id)] = 1;
        out.ids.push_back(id);
        from.push_back(k * per_tile + std::size_t(j) * l.tile + std::size_t(i));
      }
  v.surface.level = level_;
  v.surface.points.resize(from.size());
  v.surface.normals.resize(from.size());
  size_channels(v, from.size(), two_sided_);
  for (std::size_t k = 0; k < from.size(); ++k) {
    const std::size_t t = from[k];
    v.surface.points[k] = {positions[t][0], positions[t][1], positions[t][2]};
    v.surface.normals[k] = {normals[t][0], normals[t][1], normals[t][2]};
    put_channels(v, k, c, t);
  }
  displace(v);
  return out;
}

struct PaintSurface::Display
{
  std::shared_ptr<DisplayArrays> arrays;
  cl::Program program;
  cl::Kernel vertices, inside;
  cl::Buffer vertex_of;         // texel_vertices() on the device
  std::uint64_t shows = 0;      // the change_count() the arrays show; 0: nothing yet
};

std::shared_ptr<DisplayArrays> PaintSurface::display_arrays()
{
  if (!display_) {
    if (!DisplayArrays::supported(atlas_->runtime()))
      return nullptr;
    Runtime& rt = atlas_->runtime();
    auto d = std::make_shared<Display>();
    try {
      d->program = kernel_program(rt, KernelProgram::Display, storage_options(atlas_->storage(), rt.info()));
      d->vertices = cl::Kernel(d->program, "display_vertices");
      d->inside = cl::Kernel(d->program, "display_inside");
      d->vertex_of = device_ints(rt.context(), texel_vertices(state()));
    } catch (const cl::Error& e) {
      throw DeviceError("cannot set up the display arrays on " + rt.info().name + ": " + describe(e));
    }
    d->arrays = std::make_shared<DisplayArrays>(atlas_->shared_runtime(), atlas_->topology().unique_vertices(level_),
                                                two_sided_);
    display_ = d;
  }
  Display& d = *display_;
  if (d.shows != 0 && d.shows == change_count_)
    return d.arrays;
  const PatchChanges changes = changes_since(d.shows); // everything the first time
  const std::vector<int>* listed = changes.all ? nullptr : &changes.patches;
  const LevelLayout l = atlas_->layout(level_);
  const int count = listed ? int(listed->size()) : l.patches;
  Runtime& rt = atlas_->runtime();
  try {
    const PaintState st = state();
    const cl::Memory& positions = atlas_->limit_positions_layer(); // brought up to date first
    const cl::Memory& normals = atlas_->limit_normals_layer();
    const cl::Buffer list = listed ? device_ints(rt.context(), *listed) : cl::Buffer();
    // Whatever happens on the device, the arrays go back to the host:
    // viewers point at them.
    struct Remap
    {
      DisplayArrays& arrays;
      ~Remap() { arrays.end_write(); }
    } remap{*d.arrays};
    const std::vector<cl::Buffer>& out = d.arrays->begin_write();
    if (count > 0) {
      const auto tiles = range_tiles(l, count);
      const auto memory = [&](int id) -> const cl::Memory& { return *snapshot_layer(st, id).second; };
      launch(rt.queue(), d.vertices, tiles.first, tiles.second, positions, normals, memory(kDiffuse),
             memory(kSpecular), memory(kMaterial), grid(l), list, count, d.vertex_of, out[0], out[1], out[2], out[3],
             out[4], out[5], out[6], out[7], d.arrays->flags());
      if (two_sided_)
        launch(rt.queue(), d.inside, tiles.first, tiles.second, memory(kInsideDiffuse), memory(kInsideSpecular),
               memory(kInsideMaterial), grid(l), list, count, d.vertex_of, out[8], out[9], out[10], d.arrays->flags());
    }
  } catch (const cl::Error& e) {
    d.shows = 0; // written in part, if at all: all of it next time
    throw DeviceError("updating the display arrays failed on " + rt.info().name + ": " + describe(e));
  }
  d.shows = change_count_;
  return d.arrays;
}

void PaintSurface::changed(const std::vector<int>& patches)
{
  ++change_count_;
  for (const int p : patches)
    changed_at_[std::size_t(p)] = change_count_;
}

void PaintSurface::changed_all() { all_changed_at_ = ++change_count_; }

PatchChanges PaintSurface::changes_since(std::uint64_t count) const
{
  PatchChanges out;
  out.all = all_changed_at_ > count;
  if (out.all)
    return out;
  for (std::size_t p = 0; p < changed_at_.size(); ++p)
    if (changed_at_[p] > count)
      out.patches.push_back(int(p));
  return out;
}

} // namespace meshpaint
