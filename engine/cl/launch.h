// Enqueueing kernels: arguments in order, ranges rounded to whole groups.
#pragma once

#include "cl/kernel_clock.h"
#include "cl/opencl.h"

#include <algorithm> // for std::max
#include <cstddef>   // for std::size_t
#include <vector>    // for std::vector

namespace meshpaint {

inline std::size_t round_up(std::size_t x, std::size_t multiple) { return (x + multiple - 1) / multiple * multiple; }

//! Sets the kernel's arguments in order and enqueues it (timed on the
//! device while a KernelClock runs on the queue).
template <typename... Args>
void launch(cl::CommandQueue& queue, cl::Kernel& kernel, const cl::NDRange& global, const cl::NDRange& local,
            const Args&... args)
{
  cl_uint index = 0;
  (kernel.setArg(index++, args), ...);
  if (KernelClock* clock = KernelClock::of(queue)) {
    cl::Event done;
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, global, local, nullptr, &done);
    clock->record(kernel, done);
    return;
  }
  queue.enqueueNDRangeKernel(kernel, cl::NullRange, global, local);
}

//! A read-only device copy of a list of ints (one element for an empty
//! list, so it is always a valid argument).
inline cl::Buffer device_ints(const cl::Context& context, const std::vector<int>& list)
{
  static const int none = 0;
  return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(int) * std::max<std::size_t>(1, list.size()),
                    const_cast<int*>(list.empty() ? &none : list.data()));
}

} // namespace meshpaint
