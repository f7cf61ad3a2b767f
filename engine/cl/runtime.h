// OpenCL platform, device, context and queue: the engine's view of the
// compute device.
#pragma once

#include "cl/opencl.h"

#include <map>    // for std::map
#include <memory> // for std::shared_ptr
#include <string> // for std::string
#include <utility> // for std::pair
#include <vector> // for std::vector

namespace meshpaint {

//! What the engine needs to know about a device.
struct DeviceInfo
{
  int platform_index = 0;
  int device_index = 0;
  std::string platform;
  std::string name;
  std::string version;
  bool gpu = false;
  bool images = false;               //!< image2d_t supported
  bool host_memory = false;          //!< its memory is the host's (a CPU device, an integrated GPU)
  std::uint64_t global_memory = 0;   //!< bytes (at most MESHPAINT_DEVICE_MEMORY when set)
  std::uint64_t max_allocation = 0;  //!< bytes in one buffer or image (likewise)
  bool address_space_limited = false; //!< host memory capped by the address-space limit (ulimit -v)
  std::size_t image_max_width = 0;   //!< texels
  std::size_t image_max_height = 0;  //!< texels

  //! What global_memory stands for in messages: "the device's memory", or
  //! the memory left under the address-space limit.
  std::string memory_name() const;

  //! "pthread-skylake (Portable Computing Language, CPU, 23.4 GiB)"
  std::string summary() const;
};

//! A device with its context and in-order queue.
class Runtime
{
public:
  //! Opens the device named by `selector`, or by MESHPAINT_DEVICE when it is
  //! empty: "gpu", "cpu", "P:D" (platform and device index, see
  //! `meshpaint devices`) or part of a device name. Default: the first GPU,
  //! else the first CPU device.
  //! \throw DeviceError when there is no platform or no matching device.
  static std::shared_ptr<Runtime> open(const std::string& selector = "");

  //! Every device of every platform. MESHPAINT_DEVICE_MEMORY (e.g. "512M")
  //! caps the memory and largest allocation reported, as if every device had
  //! at most that much: for testing limits, or to leave memory to others.
  //! \throw DeviceError when there is no OpenCL platform; InputError when
  //! MESHPAINT_DEVICE_MEMORY is not a size.
  static std::vector<DeviceInfo> list_devices();

  const cl::Context& context() const { return context_; }
  const cl::Device& device() const { return device_; }
  cl::CommandQueue& queue() { return queue_; }
  //! Replaces the queue, once the device has finished its work, by one that
  //! keeps profiling timestamps (on) or a plain one (off): for KernelClock.
  void set_profiling(bool on);
  const DeviceInfo& info() const { return info_; }
  //! Programs built for this device, by program and build options: the
  //! store of kernel_program() (cl/kernel_programs.h).
  std::map<std::pair<int, std::string>, cl::Program>& program_cache() { return programs_; }

private:
  Runtime(const cl::Device& device, const DeviceInfo& info);

  cl::Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  DeviceInfo info_;
  std::map<std::pair<int, std::string>, cl::Program> programs_;
};

} // namespace meshpaint
