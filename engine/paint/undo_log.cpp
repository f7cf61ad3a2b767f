#include "paint/undo_log.h"

#include "core/format.h"

namespace meshpaint {

std::size_t Snapshot::bytes() const
{
  std::size_t b = patches.size() * sizeof(int);
  for (const auto& layer : layers)
    b += layer.size() * sizeof(Float4);
  return b + (memo ? memo->bytes() : 0);
}

void UndoLog::set_budget(std::size_t bytes)
{
  budget_ = bytes;
  trim();
}

void UndoLog::forget_redo()
{
  for (const Snapshot& s : redo_)
    bytes_ -= s.bytes();
  redo_.clear();
}

void UndoLog::record(Snapshot before)
{
  forget_redo();
  bytes_ += before.bytes();
  undo_.push_back(std::move(before));
  trim();
}

void UndoLog::undone(Snapshot current)
{
  bytes_ -= undo_.back().bytes();
  undo_.pop_back();
  bytes_ += current.bytes();
  redo_.push_back(std::move(current));
}

void UndoLog::redone(Snapshot current)
{
  bytes_ -= redo_.back().bytes();
  redo_.pop_back();
  bytes_ += current.bytes();
  undo_.push_back(std::move(current));
  trim();
}

void UndoLog::trim()
{
  // The oldest undo steps go first; what can be redone is newer than all.
  std::size_t dropped = 0, freed = 0;
  while (bytes_ > budget_ && !undo_.empty()) {
    freed += undo_.front().bytes();
    bytes_ -= undo_.front().bytes();
    undo_.pop_front();
    ++dropped;
  }
  if (dropped)
    messages_.push_back("undo budget " + format_bytes(budget_) + ": forgot the " + std::to_string(dropped) +
                        " oldest stroke" + (dropped == 1 ? "" : "s") + " (" + format_bytes(freed) + ")");
}

std::vector<std::string> UndoLog::take_messages()
{
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

} // namespace meshpaint
