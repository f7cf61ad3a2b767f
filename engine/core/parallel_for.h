// Work over an index range on every core of the host, for loops whose
// iterations are independent (each writes only its own results).
#pragma once

#include <algorithm>     // for std::min, std::max
#include <cstddef>       // for std::size_t
#include <exception>     // for std::exception_ptr, std::current_exception, std::rethrow_exception
#include <mutex>         // for std::mutex, std::lock_guard
#include <system_error>  // for std::system_error
#include <thread>        // for std::thread
#include <vector>        // for std::vector

namespace meshpaint {

//! Calls body(begin, end) on contiguous pieces of [0, n), one piece per
//! thread, at least `grain` indices each, and returns when all are done.
//! The first exception a piece throws is rethrown here. Where no thread can
//! be started the caller's thread does the work alone.
template <class Body>
void parallel_for(std::size_t n, std::size_t grain, Body&& body)
{
  const std::size_t cores = std::max<std::size_t>(1, std::thread::hardware_concurrency());
  const std::size_t pieces = std::max<std::size_t>(1, std::min(cores, n / std::max<std::size_t>(grain, 1)));
  if (pieces == 1) {
    body(std::size_t(0), n);
    return;
  }
  std::exception_ptr first;
  std::mutex guard;
  const auto run = [&](std::size_t begin, std::size_t end) {
    try {
      body(begin, end);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(guard);
      if (!first)
        first = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  const std::size_t size = (n + pieces - 1) / pieces;
  std::size_t mine = 0; // pieces no thread could be started for run here
  for (std::size_t p = 1; p < pieces; ++p) {
    const std::size_t begin = p * size, end = std::min(n, begin + size);
    if (begin >= end)
      break;
    try {
      threads.emplace_back(run, begin, end);
    } catch (const std::system_error&) {
      mine = p;
      break;
    }
  }
  run(0, std::min(n, size));
  if (mine != 0)
    run(mine * size, n);
  for (std::thread& t : threads)
    t.join();
  if (first)
    std::rethrow_exception(first);
}

} // namespace meshpaint
