// Wall-clock timing for benchmarks and progress reports.
#pragma once

#include <algorithm> // for std::sort
#include <chrono>    // for std::chrono::steady_clock
#include <vector>    // for std::vector

namespace meshpaint {

class Timer
{
public:
  Timer() : start_(std::chrono::steady_clock::now()) {}
  void restart() { start_ = std::chrono::steady_clock::now(); }
  double ms() const
  {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_;
};

//! Median of a non-empty sample.
inline double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace meshpaint
