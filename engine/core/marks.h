// Marks on items 0..n-1 that all clear at once.
#pragma once

#include <algorithm> // for std::sort
#include <cstddef>   // for std::size_t
#include <cstdint>   // for std::uint8_t
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

//! The items marked in `marks` (of n), in increasing order, given that
//! `listed` holds them in any order, each once: for many a scan of the
//! marks beats a sort.
inline std::vector<int> marked_in_order(std::vector<int> listed, const Marks& marks, std::size_t n)
{
  if (listed.size() * 16 <= n) {
    std::sort(listed.begin(), listed.end());
    return listed;
  }
  // Written in place: no push_back per item where `listed` holds each
  // marked item once, and right whatever it holds.
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (marks.marked(i)) {
      if (k < listed.size())
        listed[k] = int(i);
      else
        listed.push_back(int(i));
      ++k;
    }
  listed.resize(k);
  return listed;
}

} // namespace meshpaint
