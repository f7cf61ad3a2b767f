// Multiresolution editing on the atlas (Ritschel et al. 2006, section 6):
// the finest level S as a smooth surface up(down(S)) plus details in its
// local frames, so that an edit at a coarse level carries the detail along.
#pragma once

#include "atlas/atlas.h"

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

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

  //! The level the details are encoded over; -1 when there are none.
  int level() const { return level_; }
  //! After the finest level changed otherwise (a fine edit, undo, a reduce):
  //! the details no longer describe it.
  void invalidate() { level_ = -1; }

  //! Levels `level`..finest-1 become down(S) by Gaussian reduction; the
  //! details are S - up(down(S)) in the frames of up(down(S)). The finest
  //! level and its limit stay as they were, bit for bit.
  void encode(int level);

  //! Patches whose finest texels can change when the edit level changes on
  //! `patches`: the Catmull-Clark support, two faces of the edit level.
  std::vector<int> reach(const std::vector<int>& patches) const;

  //! Rebuilds the finest level from the edit level on `affected` (from
  //! reach()): up(), then the details in the new frames. Texels elsewhere
  //! keep their values bit for bit; the limit layers on `affected` are left
  //! to the caller (Atlas::update_limit).
  void reconstruct(const std::vector<int>& affected);

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

private:
  struct Device;
  //! Copies the tiles of `patches` (null: all) of the finest level.
  void copy_level(const cl::Memory& from, const cl::Memory& to, const std::vector<int>* patches = nullptr);
  //! `patches` and `rings` rings of patches around them (sharing a corner), sorted.
  std::vector<int> grow(const std::vector<int>& patches, int rings) const;

  Atlas& atlas_;
  int level_ = -1;
  std::unique_ptr<Device> device_;
  std::vector<float> extent_;      // per patch: longest grid edge at encode()
};

} // namespace meshpaint
