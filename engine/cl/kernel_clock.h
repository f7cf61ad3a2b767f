// Device time per kernel from OpenCL's profiling events: what the benchmarks
// print beside their wall times to tell where a step spends it.
#pragma once

#include "cl/runtime.h"

#include <map>     // for std::map
#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

namespace meshpaint {

//! While one lives, every kernel that launch() enqueues on its runtime's
//! queue leaves an event whose start and end the device stamps. It turns
//! the queue into a profiling one for its lifetime and back afterwards
//! (both after a wait for the device); one at a time per process.
class KernelClock
{
public:
  //! \throw std::logic_error when another clock lives; cl::Error.
  explicit KernelClock(Runtime& runtime);
  ~KernelClock();
  KernelClock(const KernelClock&) = delete;
  KernelClock& operator=(const KernelClock&) = delete;

  //! Device milliseconds per kernel name, summed over the launches since the
  //! clock began or since the last take(); waits for the device.
  std::map<std::string, double> take();

  //! The clock that times launches on `queue`, or null.
  static KernelClock* of(const cl::CommandQueue& queue);
  //! Keeps a launch's event for take().
  void record(const cl::Kernel& kernel, const cl::Event& done);

private:
  Runtime& runtime_;
  std::vector<std::pair<std::string, cl::Event>> events_;
};

} // namespace meshpaint
