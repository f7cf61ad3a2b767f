#include "host_memory.h"

#include "core/format.h"
#include "core/timer.h"

#include <algorithm> // for std::nth_element
#include <cstdint>   // for std::uint32_t
#include <numeric>   // for std::iota
#include <random>    // for std::mt19937
#include <vector>    // for std::vector

namespace meshpaint::cli {
namespace {

constexpr std::size_t kSmall = std::size_t(2) << 20, kLarge = std::size_t(64) << 20;
constexpr std::size_t kReads = std::size_t(1) << 21;

//! Median nanoseconds of a dependent read over `bytes` of memory, visited in
//! one random cycle through every line, over three timed runs of kReads.
double dependent_read_ns(std::size_t bytes)
{
  // One 32-bit index per 64-byte line, the rest of the line unused, so that
  // each read is a line of its own. Sattolo's shuffle makes one cycle
  // through every line: no read can be skipped or guessed.
  constexpr std::size_t kStride = 64 / sizeof(std::uint32_t);
  const std::size_t lines = std::max<std::size_t>(2, bytes / 64);
  std::vector<std::uint32_t> next(lines * kStride);
  std::vector<std::uint32_t> order(lines);
  std::iota(order.begin(), order.end(), 0u);
  std::mt19937 random(12345);
  for (std::size_t i = lines - 1; i > 0; --i)
    std::swap(order[i], order[std::uniform_int_distribution<std::size_t>(0, i - 1)(random)]);
  for (std::size_t i = 0; i < lines; ++i)
    next[std::size_t(order[i]) * kStride] = std::uint32_t(order[(i + 1) % lines] * kStride);
  std::vector<double> ns;
  std::uint32_t at = 0;
  for (int run = 0; run < 4; ++run) {
    const Timer timer;
    for (std::size_t k = 0; k < kReads; ++k)
      at = next[at];
    if (run > 0) // the first lap warms the caches and pages
      ns.push_back(timer.ms() * 1e6 / double(kReads));
  }
  // `at` ends the chain: without a use the loop could be dropped.
  if (at == std::uint32_t(-1))
    ns.push_back(0);
  std::nth_element(ns.begin(), ns.begin() + long(ns.size() / 2), ns.end());
  return ns[ns.size() / 2];
}

} // namespace

HostMemory probe_host_memory() { return {dependent_read_ns(kSmall), dependent_read_ns(kLarge)}; }

std::string HostMemory::text() const
{
  return "host dependent reads: 2 MiB " + format_fixed(small_ns, 0) + " ns, 64 MiB " + format_fixed(large_ns, 0) +
         " ns";
}

std::string HostMemory::json() const
{
  return "{\"2MiB\":" + std::to_string(small_ns) + ",\"64MiB\":" + std::to_string(large_ns) + "}";
}

} // namespace meshpaint::cli
