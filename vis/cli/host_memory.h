// The host's memory as the gathering kernels meet it: how long a read that
// depends on the one before takes within a working set of a given size.
// Benchmarks print it beside their tables, since on a CPU device a brush
// step's gathers wait on these reads, and hosts of the same core count
// differ in them by twice or more.
#pragma once

#include <cstddef> // for std::size_t
#include <string>  // for std::string

namespace meshpaint::cli {

//! Median nanoseconds of a dependent read over `bytes` of memory, visited in
//! one random cycle (every line once per lap), over three timed runs.
double dependent_read_ns(std::size_t bytes);

//! The probe at the sizes that tell a cache from main memory, for a
//! benchmark's header ("...: 2 MiB 21 ns, 64 MiB 128 ns") or its JSON
//! ({"2MiB":21.0,"64MiB":128.0}).
struct HostMemory
{
  double small_ns = 0, large_ns = 0;
  std::string text() const;
  std::string json() const;
};
HostMemory probe_host_memory();

} // namespace meshpaint::cli
