#include "cl/kernel_clock.h"

#include <atomic>    // for std::atomic
#include <stdexcept> // for std::logic_error

namespace meshpaint {
namespace {

std::atomic<KernelClock*> running{nullptr};

} // namespace

KernelClock::KernelClock(Runtime& runtime) : runtime_(runtime)
{
  KernelClock* none = nullptr;
  if (!running.compare_exchange_strong(none, this))
    throw std::logic_error("a second KernelClock while one runs");
  try {
    runtime_.set_profiling(true);
  } catch (...) {
    running = nullptr;
    throw;
  }
}

KernelClock::~KernelClock()
{
  running = nullptr;
  try {
    runtime_.set_profiling(false);
  } catch (const cl::Error&) {
    // A device that fails here fails the next call too, which reports it.
  }
}

KernelClock* KernelClock::of(const cl::CommandQueue& queue)
{
  KernelClock* clock = running.load();
  return clock && clock->runtime_.queue()() == queue() ? clock : nullptr;
}

void KernelClock::record(const cl::Kernel& kernel, const cl::Event& done)
{
  events_.emplace_back(kernel.getInfo<CL_KERNEL_FUNCTION_NAME>(), done);
}

std::map<std::string, double> KernelClock::take()
{
  runtime_.queue().finish();
  std::map<std::string, double> ms;
  for (const auto& [name, event] : events_) {
    const cl_ulong start = event.getProfilingInfo<CL_PROFILING_COMMAND_START>();
    const cl_ulong end = event.getProfilingInfo<CL_PROFILING_COMMAND_END>();
    ms[name] += double(end - start) * 1e-6;
  }
  events_.clear();
  return ms;
}

} // namespace meshpaint
