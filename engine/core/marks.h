// Marks on items 0..n-1 that all clear at once.
#pragma once

#include <algorithm> // for std::sort, std::min
#include <cstddef>   // for std::size_t
#include <cstdint>   // for std::uint8_t
#include <utility>   // for std::move
#include <vector>    // for std::vector

namespace meshpaint {

//! Each begin() starts a new generation instead of writing n zeros (but
//! once in 255), so a pass that marks a few items of many costs only those
//! items.
class Marks
{
public:
  //! Clears every mark, for items 0..n-1.
  void begin(std::size_t n)
  {
    if (mark_.size() != n || ++generation_ == 0) {
      mark_.assign(n, 0);
      generation_ = 1;
    }
  }
  bool marked(std::size_t i) const { return mark_[i] == generation_; }
  //! Marks item i; whether it was unmarked.
  bool mark(std::size_t i)
  {
    if (mark_[i] == generation_)
      return false;
    mark_[i] = generation_;
    return true;
  }

private:
  std::vector<std::uint8_t> mark_; // bytes: a quarter of the cache lines of wider marks
  std::uint8_t generation_ = 0;
};

//! The items i < n for which marked(i) holds, in increasing order, given
//! that `listed` holds them in any order, each once (the result has at most
//! as many): for a few a sort of `listed`, for many a scan, which writes
//! every item and keeps it by a count, no branch on the mark. The sort costs
//! about a scan's time at n / 32 items on this project's CPU hosts.
template <class Marked>
std::vector<int> in_order(std::vector<int> listed, std::size_t n, Marked marked)
{
  if (listed.size() * 32 <= n) {
    std::sort(listed.begin(), listed.end());
    return listed;
  }
  const std::size_t held = listed.size();
  listed.resize(held + 1);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n && k <= held; ++i) {
    listed[k] = int(i);
    k += marked(i);
  }
  listed.resize(std::min(k, held));
  return listed;
}

//! in_order() of the items marked in `marks`.
inline std::vector<int> marked_in_order(std::vector<int> listed, const Marks& marks, std::size_t n)
{
  return in_order(std::move(listed), n, [&marks](std::size_t i) { return marks.marked(i); });
}

} // namespace meshpaint
