// Multiresolution editing on the atlas (Ritschel et al. 2006, section 6):
// the finest level S as a smooth surface up(down(S)) plus details in its
// local frames, so that an edit at a coarse level carries the detail along.
#pragma once

#include "atlas/atlas.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint64_t
#include <memory>  // for std::unique_ptr
#include <vector>  // for std::vector

namespace meshpaint {

//! A patch whose sampling grew this much under an edit at a coarse level
//! is undersampled there: the user should edit at a finer level.
constexpr float kUndersampledStretch = 2.f;

class Multires
{
public:
  explicit Multires(Atlas& atlas);
  ~Multires();
  Multires(const Multires&) = delete;
  Multires& operator=(const Multires&) = delete;

  //! Which encoding is in place and whether it is in use: what an undo
  //! step needs to give the details back.
  struct State
  {
    int level = -1;               //!< the edit level in use; -1: none
    std::uint64_t generation = 0; //!< which encoding (each encode() makes a new one)
  };
  //! An encoding copied to the host, to be put back after a later one
  //! replaced it (undo across a re-encoding).
  struct Memo
  {
    State state;                           //!< level: the level encoded
    std::vector<Float4> details;
    std::vector<float> extent;
    std::vector<std::vector<Float4>> levels; //!< control points of state.level .. finest - 1
    std::size_t bytes() const;
  };

  //! The level the details are encoded over and in use; -1 when none.
  int level() const { return level_; }
  //! The level of the encoding in place, in use or not; -1 when none.
  int encoded_level() const { return encoded_level_; }
  State state() const { return {level_, generation_}; }
  //! The finest level was edited (a stroke at the finest level): the details
  //! no longer describe it, but stay in place for an undo of that edit.
  void detach() { level_ = -1; }
  //! The levels below the finest were rewritten otherwise (a reduction, a
  //! new surface): the encoding is gone.
  void invalidate();
  //! Puts `state` back in use if its encoding is the one in place; else
  //! leaves the details unused and returns false.
  bool resume(const State& state);
  //! The encoding in place, copied to the host.
  Memo save();
  //! Puts a saved encoding back in place (not in use: resume() it).
  void load(const Memo& memo);

  //! Levels `level`..finest-1 become down(S) by Gaussian reduction; the
  //! details are S - up(down(S)) in the frames of up(down(S)). The finest
  //! level and its limit stay as they were, bit for bit.
  void encode(int level);

  //! Patches whose finest texels can change when the edit level changes on
  //! `patches`, where every patch holding a copy of a moved point is in
  //! `patches`: they and one ring around them.
  std::vector<int> reach(const std::vector<int>& patches) const;

  //! Rebuilds the finest level from the edit level on `affected` (from
  //! reach(), so in patch order, each once): up(), then the details in the
  //! new frames. Texels elsewhere keep their values bit for bit; the limit
  //! layers on `affected` are left to the caller (Atlas::update_limit).
  void reconstruct(const std::vector<int>& affected);
  //! The same, given Atlas::neighbourhood(affected), which the caller's
  //! limit update takes too (this makes no set of its own).
  void reconstruct(const std::vector<int>& affected, const PatchSet& around);

  //! Worst growth of a patch's longest finest-level grid edge since
  //! encode(), over `patches`: how far the edit level undersamples.
  float stretch(const std::vector<int>& patches);

  //! The limit surface of the edit level's control points on the tiles of
  //! `patches`, which a brush at that level weighs and moves them by:
  //! smooth, without the details.
  void compute_base_limit(const std::vector<int>& patches);
  const cl::Memory& base_positions() const;
  const cl::Memory& base_normals() const;
  //! Per-texel brush weights at the edit level.
  //! The details, per finest texel (patch-major): coordinates along the
  //! tangent, the bitangent and the normal.
  std::vector<Float4> read_details();

  const cl::Buffer& base_weights() const;

  //! Device bytes a Multires on `atlas` allocates (the details, the edit
  //! level's limit and weights, U where it has a layer, per-patch values),
  //! to be checked before one is made.
  static std::size_t device_bytes(const Atlas& atlas);
  //! The same for an atlas of `patches` patches up to `finest` that is yet
  //! to be made, its evaluator's patch_items() being `patch_items`.
  static std::size_t device_bytes(int patches, int finest, AtlasStorage storage, bool patch_items);
  //! Bytes of the device objects this Multires holds, as the driver reports
  //! them (CL_MEM_SIZE): what device_bytes() plans, where nothing pads.
  std::size_t allocated_bytes() const;

private:
  struct Device;

  Atlas& atlas_;
  int level_ = -1;         // in use
  int encoded_level_ = -1; // in place
  std::uint64_t generation_ = 0;
  std::unique_ptr<Device> device_;
  std::vector<float> extent_;      // per patch: longest grid edge at encode()
};

} // namespace meshpaint
