#include "device_bandwidth.h"

#include "cl/kernel_programs.h"
#include "cl/launch.h"
#include "core/format.h"
#include "core/timer.h"

#include <algorithm> // for std::min
#include <vector>    // for std::vector

namespace meshpaint::cli {
namespace {

constexpr int kCopies = 7;

//! Median GB/s (read + write) of `copy` run kCopies times after a warm-up.
template <typename Copy>
double copy_gbps(cl::CommandQueue& queue, std::size_t bytes, Copy copy)
{
  copy();
  queue.finish();
  std::vector<double> ms;
  for (int k = 0; k < kCopies; ++k) {
    const Timer t;
    copy();
    queue.finish();
    ms.push_back(t.ms());
  }
  return 2.0 * double(bytes) / (median(ms) * 1e6);
}

} // namespace

std::string DeviceBandwidth::text() const
{
  return "device copy: clEnqueueCopyBuffer " + format_fixed(enqueue_copy_gbps, 1) + " GB/s, copy kernel " +
         format_fixed(kernel_copy_gbps, 1) + " GB/s (read + write, 2 x " + format_fixed(mib, 0) + " MiB)";
}

std::string DeviceBandwidth::json() const
{
  return "{\"enqueue_copy\":" + std::to_string(enqueue_copy_gbps) + ",\"copy_kernel\":" +
         std::to_string(kernel_copy_gbps) + ",\"mib\":" + std::to_string(mib) + "}";
}

DeviceBandwidth probe_device_bandwidth(Runtime& runtime)
{
  // Far beyond a CPU's last-level cache or a GPU's L2, within one allocation.
  const std::size_t bytes =
    std::min<std::size_t>(std::size_t(256) << 20, std::size_t(runtime.info().max_allocation) / 2) / 16 * 16;
  const cl::Context& context = runtime.context();
  cl::CommandQueue& queue = runtime.queue();
  cl::Buffer src(context, CL_MEM_READ_WRITE, bytes), dst(context, CL_MEM_READ_WRITE, bytes);
  queue.enqueueFillBuffer(src, cl_uint(0x3f800000), 0, bytes); // every page touched before timing
  queue.enqueueFillBuffer(dst, cl_uint(0), 0, bytes);
  DeviceBandwidth b;
  b.mib = double(bytes) / double(1 << 20);
  b.enqueue_copy_gbps = copy_gbps(queue, bytes, [&] { queue.enqueueCopyBuffer(src, dst, 0, 0, bytes); });
  cl::Kernel kernel(kernel_program(runtime, KernelProgram::Copy, "-cl-std=CL1.2"), "copy_float4");
  const cl_int count = cl_int(bytes / 16);
  b.kernel_copy_gbps = copy_gbps(queue, bytes, [&] {
    launch(queue, kernel, cl::NDRange(round_up(std::size_t(count), 256)), cl::NDRange(256), src, dst, count);
  });
  return b;
}

} // namespace meshpaint::cli
