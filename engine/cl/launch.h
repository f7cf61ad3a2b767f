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

//! A read-only device copy of `v` (one zero element for an empty one, so it
//! is always a valid argument).
template <typename T>
cl::Buffer device_copy(const cl::Context& context, const std::vector<T>& v)
{
  static const T none{};
  return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(T) * std::max<std::size_t>(1, v.size()),
                    const_cast<T*>(v.empty() ? &none : v.data()));
}

//! A read-only device copy of one value (a kernel's struct argument),
//! made from host memory at once: no command on the queue waits for it,
//! and commands queued with the buffer it replaces keep that one.
template <typename T>
cl::Buffer device_value(const cl::Context& context, const T& v)
{
  return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(T), const_cast<T*>(&v));
}

//! device_copy() of a list of ints.
inline cl::Buffer device_ints(const cl::Context& context, const std::vector<int>& list)
{
  return device_copy(context, list);
}

} // namespace meshpaint
