// The host's memory as the gathering kernels meet it: how long a read that
// depends on the one before takes within a working set of a given size.
// Benchmarks print it beside their tables, since on a CPU device a brush
// step's gathers wait on these reads, so figures from different hosts are
// compared with it beside them.
#pragma once

#include <cstddef> // for std::size_t
#include <string>  // for std::string

namespace meshpaint::cli {

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
