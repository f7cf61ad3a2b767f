// A surface to paint on: the atlas at the painting level, its limit surface,
// the paint channels, the undo and change logs, and a stroke's way through
// the brush pipeline, which hands each dab to its tool family: free
// functions or small classes over its PaintState and a DabContext
// (colour_paint.h, smoothing.h, sculpt.h, grab.h, coarse_edit.h, reshape.h,
// label_edits.h), after brush_placement.h and brush_space.h placed it;
// snapshots.h and subsurface_light.h work on the state too. Reading the
// surface back lives in painted_surface.cpp, what fits in paint_memory.h.
#pragma once

#include "atlas/atlas.h"
#include "atlas/multires.h"
#include "core/timer.h"
#include "mesh/welded_surface.h"
#include "paint/brush_placement.h"
#include "paint/coarse_edit.h"
#include "paint/dab_context.h"
#include "paint/display_arrays.h"
#include "paint/label_edits.h"
#include "paint/paint_state.h"
#include "paint/stroke.h"
#include "paint/stroke_report.h"
#include "paint/undo_log.h"

#include <cstdint> // for std::uint64_t
#include <memory>  // for std::unique_ptr
#include <vector> // for std::vector

namespace meshpaint {

//! The channels as host arrays, patch-major (LevelLayout::index).
struct PaintChannels
{
  std::vector<Float4> diffuse;  //!< rgb
  std::vector<Float4> specular; //!< rgb
  std::vector<Float4> material; //!< (roughness, displacement, label, mask)
  //! Two-sided surfaces: the inside's diffuse, specular and material (of
  //! which roughness and mask count; displacement and labels are the
  //! surface's, in `material`). Empty otherwise.
  std::vector<Float4> inside_diffuse, inside_specular, inside_material;
};

//! The welded limit surface with its channels per vertex; points are
//! displaced along the normal by the displacement channel (P = P0 + h N).
struct PaintedSurface
{
  WeldedSurface surface;
  std::vector<Vec3> diffuse, specular;
  std::vector<float> roughness, displacement, mask;
  std::vector<int> label;
  //! Two-sided surfaces: the inside's channels; empty otherwise.
  std::vector<Vec3> inside_diffuse, inside_specular;
  std::vector<float> inside_roughness;
};

//! painted_surface()'s values at some of its welded vertices.
struct PaintedVertices
{
  std::vector<int> ids;  //!< welded vertex ids, each once
  PaintedSurface values; //!< one entry per id in each array (surface.quads empty)
};

//! Which patches changed after a moment (PaintSurface::change_count()).
struct PatchChanges
{
  bool all = false;         //!< anything may have changed: read the whole surface
  std::vector<int> patches; //!< else these, ascending
};

//! Default material of unpainted surface.
struct BaseMaterial
{
  Float4 diffuse{0.8f, 0.8f, 0.8f, 1.f};
  Float4 specular{0.04f, 0.04f, 0.04f, 1.f};
  float roughness = 0.5f;
};

//! The surface keeps the state; its tool families see the running stroke
//! through StrokeHooks, which it implements (undo records, phase timing).
class PaintSurface : private StrokeHooks
{
public:
  //! Subdivides `mesh` to `level` on the device and computes its limit
  //! surface, patch bounds and default channels.
  PaintSurface(std::shared_ptr<Runtime> runtime, const BaseMesh& mesh, int level, AtlasStorage storage,
               const BaseMaterial& material = BaseMaterial());
  ~PaintSurface();
  PaintSurface(const PaintSurface&) = delete;
  PaintSurface& operator=(const PaintSurface&) = delete;

  Atlas& atlas() { return *atlas_; }
  int level() const { return level_; }
  //! What the tool families work on (subsurface_light.h, label_edits.h,
  //! snapshots.h, brush_placement.h, brush_space.h; with dab_context() the
  //! brushes).
  PaintState state() { return PaintState{*atlas_, level_, *device_, weld_map_, multires_}; }

  //! Two-sided materials: an inside set of diffuse, specular and roughness
  //! (starting as the base material), painted where the brush sees the
  //! surface from behind (Stroke::side). Off by default; turning it on
  //! starts a fresh undo history.
  void set_two_sided(bool on);
  bool two_sided() const { return two_sided_; }

  //! Runs the stroke's dabs in order. A dab whose centre has no surface
  //! within its radius ends the stroke (left_surface).
  StrokeReport apply(const Stroke& stroke);
  //! The same for the dabs (samples along the path, see stroke_samples())
  //! whose entry in `dabs` is non-zero only: a scene hands each object its
  //! dabs. The stroke does not end on its own where it leaves this surface.
  StrokeReport apply(const Stroke& stroke, const std::vector<char>& dabs);

  //! A stroke painted while it is drawn, in three steps that apply() takes
  //! at once: painting a path in pieces gives the bits of applying it whole.
  //! begin_stroke() takes the stroke's settings (its path may be partial).
  //! \throw InputError when a stroke is open already, or edit_level is finer
  //! than level().
  void begin_stroke(const Stroke& stroke);
  //! Paints the samples from the first not painted yet on: `samples` are
  //! stroke_samples() of the path so far, each final (a path of one point
  //! has none yet: its first dab's heading waits for the second point).
  //! `dabs` as in apply(). False once the stroke has left the surface.
  bool paint_dabs(const std::vector<DabSample>& samples, const std::vector<char>* dabs = nullptr);
  //! Ends the open stroke, `stroke` being it with its whole path (all of
  //! whose samples were painted): one undo step, one entry of history().
  StrokeReport end_stroke(const Stroke& stroke);
  bool stroke_open() const { return open_ != nullptr; }

  //! Distance from `point` to the closest surface point within `radius`;
  //! infinity when there is none (BrushPlacement::distance_to).
  float distance_to(const Vec3& point, float radius);

  //! The patches one dab at `point` would touch (BrushPlacement::brush_patches).
  std::vector<int> brush_patches(const Vec3& point, float radius, Vec3* centre = nullptr,
                                 Vec3* centre_normal = nullptr, float reach = 0.f, CullRecord* closest = nullptr);

  //! Where the next dab is expected to snap: patch `patch` at (u, v) in
  //! [0, 1]^2, as a picker reports it. Only the search gets cheaper: any
  //! texel gives every dab the same centre and patches. Out of range (a
  //! patch < 0): no hint.
  void hint_snap(int patch, double u, double v);

  //! After positions were written from outside (Atlas::write_positions):
  //! recomputes the limit surface and patch bounds everywhere.
  void geometry_changed();

  PaintChannels read_channels();
  //! Replaces every channel (e.g. from a saved project); each layer must
  //! hold the painting level's texels.
  //! \throw InputError when a layer has another size.
  void write_channels(const PaintChannels& channels);
  PaintedSurface painted_surface();
  //! painted_surface()'s values at the welded vertices of `patches` only,
  //! read from those tiles alone: for displays that follow the brush.
  PaintedVertices painted_vertices(const std::vector<int>& patches);
  //! painted_surface()'s arrays in device buffers in host memory, which a
  //! viewer draws from without a copy: made on first use, and brought up to
  //! date by every call, on the device, for the patches changed since the
  //! last (DisplayArrays says which arrays changed). Null where the
  //! device's memory is its own (use painted_vertices() there).
  std::shared_ptr<DisplayArrays> display_arrays();
  //! A count that grows with every change of the surface, and what changed
  //! after a given count: a display keeps the count of what it shows.
  std::uint64_t change_count() const { return change_count_; }
  PatchChanges changes_since(std::uint64_t count) const;
  //! Level of detail: the surface at a coarser level (<= level(), reduced
  //! from the finest), with the finest level's limit normals and channels
  //! at the matching texels.
  PaintedSurface painted_surface(int level);

  //! The strokes applied so far, in order; undo() takes the last one off,
  //! redo() puts it back.
  const std::vector<Stroke>& history() const { return history_; }
  //! The strokes undone and not yet redone, the next to redo last.
  const std::vector<Stroke>& undone() const { return undone_; }

  //! Undo and redo whole strokes; false when there is nothing to undo
  //! (redo). Undoing everything gives back the channels bit for bit.
  bool undo();
  bool redo();
  //! Undoes the last stroke for good (one that failed or was refused): it
  //! leaves history() and cannot be redone. False when nothing was undone.
  bool take_back();
  UndoLog& undo_log() { return undo_; }
  //! Times each phase of a dab into StrokeReport::phases, waiting for the
  //! device at the end of each (for benchmarks: the waits cost a little).
  void time_phases(bool on) { time_phases_ = on; }

private:
  bool step(bool back); // undo (back) or redo
  //! What a dab's tool family works with: the state, this surface's hooks,
  //! the side painted and the mask flag.
  DabContext dab_context() { return DabContext{state(), *this, inside_, mask_painted_}; }
  //! place() for the tool families that place dabs of their own (spray, grab).
  PlaceDab placer();
  //! A label edit (label_edits.h) as part of the running stroke: its tiles
  //! remembered for undo, then written.
  void record_labels(LabelEdit edit);
  struct OpenStroke;
  StrokeReport apply(const Stroke& stroke, const std::vector<char>* dabs);
  //! The open stroke's dab settings from the stroke (a wash or dip is
  //! painted here, having no path).
  void prepare_dab(const Stroke& stroke);
  //! One sample's dab, and its mirror image; `may_end`: a miss ends the stroke.
  void paint_sample(const DabSample& sample, bool may_end);
  //! Runs part of the open stroke; where it throws, the stroke is closed
  //! (one undo step, in history()) and the error passed on, OpenCL's as a
  //! DeviceError.
  template <typename F>
  void in_stroke(F&& work);
  void close_stroke(const Stroke& stroke);
  //! The side of a two-sided surface the dab paints, or the side a one-sided
  //! surface shows the stroke's camera: BrushDab::side_sign (and inside_).
  void choose_side(const Stroke& stroke, const Vec3& point, const Vec3& normal, BrushDab& dab);
  //! Finds the dab's site and aims it: the patches it may change, empty
  //! when it misses the surface (or meets a silhouette).
  std::vector<int> place(const Stroke& stroke, const DabSample& sample, BrushDab& dab, Vec3& normal);
  //! Puts back a snapshot's tiles and its state of the multiresolution details.
  void restore(const Snapshot& snapshot);
  //! StrokeHooks: the patches not yet in the stroke's snapshot, added
  //! before they change; the encoding of details a coarse edit replaces.
  void remember(const std::vector<int>& patches) override;
  void remember_details() override;
  //! With time_phases() on: waits for the device and adds the time since
  //! the last call (or phase_start()) to `phase`.
  void phase_start() override;
  void phase_done(double StepPhases::*phase) override;
  //! Records a change of these patches, or of everything, for changes_since().
  void changed(const std::vector<int>& patches);
  void changed_all();

  std::unique_ptr<Atlas> atlas_;
  int level_;
  std::unique_ptr<Multires> multires_; // details for edits at a coarser level, made on first use
  CoarseEdits coarse_;                 // what the running stroke's coarse edits rebuilt, and their encoding time
  bool mask_painted_ = false;          // a mask may be set somewhere (else weights skip reading it)
  bool time_phases_ = false;
  StepPhases phases_;                  // the running stroke's, with time_phases_
  Timer phase_clock_;
  std::vector<Stroke> history_, undone_;
  std::unique_ptr<PaintDevice> device_;
  BaseMaterial base_material_;
  UndoLog undo_;
  Snapshot stroke_before_;            // the running stroke's snapshot
  std::vector<int> stroke_layers_;    // the layers the running stroke changes
  std::vector<char> in_stroke_;       // per patch: already in stroke_before_
  BrushPlacement placement_; // the flood that finds a dab's patches, with its scratch
  std::unique_ptr<OpenStroke> open_; // the stroke being drawn
  bool two_sided_ = false;
  bool inside_ = false; // the running dab paints the inside
  std::uint64_t change_count_ = 1, all_changed_at_ = 1;
  std::vector<std::uint64_t> changed_at_; // per patch: the count of its last change
  std::vector<int> weld_map_;             // per texel of the painting level: its welded vertex (texel_vertices())
  struct Display;
  std::shared_ptr<Display> display_;      // display_arrays() and their kernels, made on first use
};

} // namespace meshpaint
