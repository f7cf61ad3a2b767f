// Enqueueing kernels: arguments in order, ranges rounded to whole groups.
#pragma once

#include "cl/opencl.h"

#include <cstddef> // for std::size_t

namespace meshpaint {

inline std::size_t round_up(std::size_t x, std::size_t multiple) { return (x + multiple - 1) / multiple * multiple; }

//! Sets the kernel's arguments in order and enqueues it.
template <typename... Args>
void launch(cl::CommandQueue& queue, cl::Kernel& kernel, const cl::NDRange& global, const cl::NDRange& local,
            const Args&... args)
{
  cl_uint index = 0;
  (kernel.setArg(index++, args), ...);
  queue.enqueueNDRangeKernel(kernel, cl::NullRange, global, local);
}

} // namespace meshpaint
