// Undo and redo per stroke: snapshots of the patches a stroke changed,
// within a memory budget.
#pragma once

#include "atlas/multires.h"
#include "core/vec.h"

#include <cstddef> // for std::size_t
#include <deque>   // for std::deque
#include <memory>  // for std::shared_ptr
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

//! The tiles of some patches in every painted layer, and the multiresolution
//! details, as they were.
struct Snapshot
{
  std::vector<int> patches;                //!< in the order of the tiles below
  std::vector<int> layer_ids;              //!< which layers (PaintSurface's numbering)
  std::vector<std::vector<Float4>> layers; //!< per layer: #patches x tile^2 texels
  int edit_level = 0;                      //!< the level of an edit-level layer among them
  Multires::State multires;                //!< the multiresolution details in use then
  //! The encoding in place then, where the step replaced it with another.
  std::shared_ptr<const Multires::Memo> memo;
  std::size_t bytes() const;
};

class UndoLog
{
public:
  //! Default budget: 512 MiB of snapshots.
  explicit UndoLog(std::size_t budget_bytes = std::size_t(512) << 20) : budget_(budget_bytes) {}

  void set_budget(std::size_t bytes);
  //! With recording off, strokes take no snapshots at all (benchmarks,
  //! batch jobs that never undo).
  void set_recording(bool on) { recording_ = on; }
  bool recording() const { return recording_; }
  std::size_t budget() const { return budget_; }
  std::size_t bytes() const { return bytes_; }

  //! A new stroke's "before" snapshot; forgets what could be redone and the
  //! oldest strokes beyond the budget (each noted in messages()).
  void record(Snapshot before);

  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  std::size_t undo_depth() const { return undo_.size(); }
  std::size_t redo_depth() const { return redo_.size(); }
  //! The snapshot to restore for undo (redo); then call undone (redone)
  //! with the current state of the same patches, taken before restoring.
  const Snapshot& next_undo() const { return undo_.back(); }
  const Snapshot& next_redo() const { return redo_.back(); }
  void undone(Snapshot current);
  void redone(Snapshot current);
  //! Forgets what could be redone.
  void forget_redo();

  //! Notes for the user since the last call ("undo budget: forgot ...").
  std::vector<std::string> take_messages();

private:
  void trim();

  std::size_t budget_;
  std::size_t bytes_ = 0;
  bool recording_ = true;
  std::deque<Snapshot> undo_;
  std::vector<Snapshot> redo_;
  std::vector<std::string> messages_;
};

} // namespace meshpaint
