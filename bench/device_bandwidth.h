// The device's copy bandwidth: what a kernel that only streams its data
// could reach there, the ceiling the achieved-bandwidth columns of the
// benchmarks are read against.
#pragma once

#include "cl/runtime.h"

#include <string> // for std::string

namespace meshpaint::cli {

//! Bytes read + written per second by a copy between two device buffers
//! far larger than any cache, GB/s: clEnqueueCopyBuffer and a copy kernel
//! (kernels/copy.cl), each the median of several copies after a warm-up.
struct DeviceBandwidth
{
  double enqueue_copy_gbps = 0;
  double kernel_copy_gbps = 0;
  double mib = 0; //!< size of each buffer
  //! The better of the two: what the device can copy.
  double best() const { return enqueue_copy_gbps > kernel_copy_gbps ? enqueue_copy_gbps : kernel_copy_gbps; }
  //! "device copy: clEnqueueCopyBuffer 21.3 GB/s, copy kernel 30.1 GB/s (2 x 256 MiB)"
  std::string text() const;
  //! {"enqueue_copy":21.3,"copy_kernel":30.1,"mib":256}
  std::string json() const;
};

//! \throw cl::Error when the device cannot hold or copy the buffers.
DeviceBandwidth probe_device_bandwidth(Runtime& runtime);

} // namespace meshpaint::cli
