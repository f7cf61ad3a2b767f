// What a painting surface keeps on the device, and the kernels it runs
// there: shared by the files of the brush pipeline (PaintSurface and the
// tool families that work on its PaintState), included by nothing else.
#pragma once

#include "cl/append_buffer.h"
#include "cl/launch.h"
#include "cl/kernel_programs.h"
#include "paint/grab.h"
#include "paint/paint_surface.h"
#include "paint/welded_smoothing.h"

#include "core/timer.h"

#include <array>    // for std::array
#include <memory>   // for std::unique_ptr
#include <optional> // for std::optional

namespace meshpaint {

//! Work items per group of the one-dimensional launches (a patch or a
//! droplet each).
constexpr std::size_t kGroup = 64;

//! Kernels that filter or copy a layer, built for one storage path.
struct LayerKernels
{
  cl::Program program;
  cl::Kernel copy_tiles, gather_tiles, scatter_tiles;
  WeldedSmoothing::LayerKernels welded;

  void build(Runtime& rt, AtlasStorage storage)
  {
    program = kernel_program(rt, KernelProgram::Brush, storage_options(storage, rt.info()));
    copy_tiles = cl::Kernel(program, "copy_tiles");
    welded.gather = cl::Kernel(program, "welded_gather");
    welded.scatter = cl::Kernel(program, "welded_scatter");
    gather_tiles = cl::Kernel(program, "gather_tiles");
    scatter_tiles = cl::Kernel(program, "scatter_tiles");
  }
};

//! Device state of the brush pipeline. Positions live in the atlas's
//! storage; paint channels, weights and lists are always buffers, so their
//! kernels come from a buffer build (the same one when the atlas uses
//! buffers).
struct PaintDevice
{
  LayerKernels positions, channels;
  cl::Kernel brush_cull, brush_cull_clusters, brush_cull_seed, brush_snap, brush_reach, brush_reach_clusters;
  cl::Kernel paint_dab, paint_patches, dab_weights, dab_weights_patches, move_points, move_points_patches, move_dab,
    move_dab_patches, move_dab_lanes;
  cl::Kernel dab_pickup;
  cl::Kernel spray_pick, spray_points;
  cl::Buffer counters, dab, weights; // dab: the BrushDab of the dab under way
  cl::Buffer open_sides;               // brush_reach: a byte per patch
  cl::Buffer snap_centre, snap_record; // brush_snap: the centre (float4) and its record's index (int)
  AppendBuffer culled;                 // CullRecord
  cl::Buffer unfold; // a parameter dab's PatchUnfolding per listed patch (one entry otherwise)
  cl::Buffer diffuse, specular, material, channel_work;
  cl::Buffer inside_diffuse, inside_specular, inside_material; // two-sided surfaces
  cl::Buffer raster, stamp; // the stroke's pattern samples and brush image (one float when none)
  cl::Buffer locked;        // the stroke's locked label classes (one int when none)
  cl::Memory position_work; // image storage: a scratch layer of the finest level for moves
  std::unique_ptr<WeldedSmoothing> smoothing;
};

//! The stroke being drawn: what its dabs share, and how far it has come.
struct PaintSurface::OpenStroke
{
  Stroke stroke;
  BrushDab dab{};
  float mirror_at = 0.f;                           // the mirror plane's position on its axis
  std::optional<std::array<Float4, 2>> carried[2]; // the smear brush's load per side of the mirror
  std::size_t next = 0;                            // samples painted or passed over so far
  bool ended = false;                              // left the surface: no later dab is painted
  float facing_side = 0.f; // a camera's stroke on one side: the side its first dab saw (1 or -1; 0: none yet)
  GrabRegion grab;
  StrokeReport report;
  Timer timer;
};

} // namespace meshpaint
