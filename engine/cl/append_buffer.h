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

//! Records read back with the count, in the same wait: on PoCL each
//! blocking read costs a wake of the device's threads and of the host, more
//! than reading this many records that may not be there.
constexpr std::size_t kRecordsWithCount = 64;

//! Runs a kernel over `items` work items (in groups of `group`) that
//! appends records of type Record (its last three arguments: the records,
//! two counters and the capacity), at most `records_max` of them, and reads
//! back what it appended, in no particular order. The counters start each
//! run at `start`; the first counts the records, the second is the
//! kernel's own, which `prepare()` may change by enqueueing work after they
//! are set and before the kernel runs. `follow()` may enqueue work after
//! the kernel that uses the records on the device, done when this returns.
//! A buffer found too small grows and the kernel, with prepare() and
//! follow(), runs again: a run may append more than the one before (the
//! kernel's own counter may fall in another order), so it grows to twice
//! the count, and at records_max no run can outgrow it.
template <typename Record, typename Prepare, typename Follow, typename... Args>
std::vector<Record> run_appending(Runtime& rt, cl::Kernel& kernel, int items, std::size_t records_max,
                                  std::size_t group, AppendBuffer& out, const cl::Buffer& counters, cl_int2 start,
                                  const Prepare& prepare, const Follow& follow, const Args&... args)
{
  cl_int count = 0;
  std::vector<Record> records;
  records_max = std::max<std::size_t>(records_max, 1);
  for (;;) {
    if (out.capacity == 0) {
      out.capacity = std::min<std::size_t>(records_max, 4096);
      out.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(Record) * out.capacity);
    }
    rt.queue().enqueueFillBuffer(counters, start, 0, sizeof start); // no wait: the queue is in order
    prepare();
    launch(rt.queue(), kernel, cl::NDRange(round_up(std::size_t(items), group)), cl::NDRange(group), args...,
           out.records, counters, cl_int(out.capacity));
    follow();
    // The count and the first records in one wait: the queue is in order,
    // so the count and what follow() enqueued are done once the records
    // have arrived.
    records.resize(std::min(out.capacity, kRecordsWithCount));
    rt.queue().enqueueReadBuffer(counters, CL_FALSE, 0, sizeof count, &count);
    rt.queue().enqueueReadBuffer(out.records, CL_TRUE, 0, sizeof(Record) * records.size(), records.data());
    if (std::size_t(count) <= out.capacity || out.capacity >= records_max)
      break;
    out.capacity = std::min(records_max, 2 * std::size_t(count));
    out.records = cl::Buffer(rt.context(), CL_MEM_READ_WRITE, sizeof(Record) * out.capacity);
  }
  count = std::min<cl_int>(count, cl_int(out.capacity)); // only past records_max, which the kernel cannot pass
  const std::size_t read = records.size();
  records.resize(static_cast<std::size_t>(count));
  if (records.size() > read)
    rt.queue().enqueueReadBuffer(out.records, CL_TRUE, sizeof(Record) * read, sizeof(Record) * (records.size() - read),
                                 records.data() + read);
  return records;
}

} // namespace meshpaint
