// Kernels that append records of varying number: a device buffer that grows
// to what a run needed, and the host side of one such run.
#pragma once

#include "cl/launch.h"
#include "cl/runtime.h"

#include <algorithm> // for std::min, std::max
#include <cstddef>   // for std::size_t
#include <vector>    // for std::vector

namespace meshpaint {

//! A kernel's appended records.
struct AppendBuffer
{
  cl::Buffer records;
  std::size_t capacity = 0;
};

//! Runs a kernel over `items` work items (in groups of `group`) that
//! appends records of type Record (its last three arguments: the records,
//! two counters and the capacity) and reads back what it appended, in no
//! particular order. The counters start each run at `start`; the first
//! counts the records, the second is the kernel's own, which `prepare()`
//! may change by enqueueing work after they are set and before the kernel
//! runs. A buffer found too small grows and the kernel runs once more.
template <typename Record, typename Prepare, typename... Args>
std::vector<Record> run_appending(Runtime& rt, cl::Kernel& kernel, int items, std::size_t group, AppendBuffer& out,
                                  const cl::Buffer& counters, cl_int2 start, const Prepare& prepare,
                                  const Args&... args)
{
  cl_int count = 0;
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (out.capacity == 0) {
      out.capacity = std::min<std::size_t>(std::max(items, 1), 4096);
      out.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(Record) * out.capacity);
    }
    rt.queue().enqueueFillBuffer(counters, start, 0, sizeof start); // no wait: the queue is in order
    prepare();
    launch(rt.queue(), kernel, cl::NDRange(round_up(std::size_t(items), group)), cl::NDRange(group), args...,
           out.records, counters, cl_int(out.capacity));
    rt.queue().enqueueReadBuffer(counters, CL_TRUE, 0, sizeof count, &count);
    if (std::size_t(count) <= out.capacity)
      break;
    out.capacity = std::size_t(count);
    out.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(Record) * out.capacity);
  }
  std::vector<Record> records(static_cast<std::size_t>(count));
  if (count > 0)
    rt.queue().enqueueReadBuffer(out.records, CL_TRUE, 0, sizeof(Record) * std::size_t(count), records.data());
  return records;
}

} // namespace meshpaint
