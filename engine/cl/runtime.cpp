#include "cl/runtime.h"

#include "cl/quirks.h"
#include "core/errors.h"
#include "core/format.h"

#include <algorithm> // for std::search, std::min
#include <cctype>    // for std::tolower
#include <cstdio>    // for std::snprintf, std::fopen, std::fscanf
#include <cstdlib>   // for std::getenv
#include <string>    // for std::string, std::to_string

#include <sys/resource.h> // for getrlimit, RLIMIT_AS
#include <unistd.h>       // for sysconf

namespace meshpaint {
namespace {


struct Found
{
  cl::Device device;
  DeviceInfo info;
};

std::string lower(std::string s)
{
  for (char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

//! MESHPAINT_DEVICE_MEMORY: bytes, or a number with K, M or G (binary
//! units); 0 when unset.
//! \throw InputError when it is set but not such a size.
std::uint64_t memory_cap()
{
  const char* text = std::getenv("MESHPAINT_DEVICE_MEMORY");
  return text && *text ? parse_memory_size("MESHPAINT_DEVICE_MEMORY", text) : 0;
}

//! Bytes of address space this process may still map under its limit
//! (ulimit -v), halved for the host's own copies; 0 when there is no limit.
//! A device in host memory is treated as having no more, so plans that do
//! not fit are refused before the driver fails to allocate.
std::uint64_t address_space_left()
{
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
    return 0;
  unsigned long long pages = 0;
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%llu", &pages) != 1)
      pages = 0;
    std::fclose(statm);
  }
  const std::uint64_t used = std::uint64_t(pages) * std::uint64_t(sysconf(_SC_PAGESIZE));
  const std::uint64_t left = limit.rlim_cur > used ? std::uint64_t(limit.rlim_cur) - used : 0;
  return std::max<std::uint64_t>(left / 2, 1);
}

//! A driver that cannot start under a low address-space limit looks like
//! no driver at all: say which it more likely is.
std::string missing(const std::string& what)
{
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    return "out of host memory: " + what + " under the address-space limit of " +
           std::to_string(std::uint64_t(limit.rlim_cur) >> 20) + " MiB (ulimit -v)";
  return what + ": install PoCL for the CPU (apt-get install pocl-opencl-icd) or a GPU vendor's OpenCL driver";
}

std::vector<Found> enumerate()
{
  apply_runtime_quirks();
  std::vector<cl::Platform> platforms;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error&) {
    throw DeviceError(missing("no OpenCL platform found"));
  }
  if (platforms.empty())
    throw DeviceError(missing("no OpenCL platform found"));

  std::vector<Found> found;
  for (std::size_t p = 0; p < platforms.size(); ++p) {
    std::vector<cl::Device> devices;
    try {
      platforms[p].getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue; // a platform without devices
    }
    for (std::size_t d = 0; d < devices.size(); ++d) {
      const cl::Device& dev = devices[d];
      DeviceInfo info;
      info.platform_index = static_cast<int>(p);
      info.device_index = static_cast<int>(d);
      info.platform = platforms[p].getInfo<CL_PLATFORM_NAME>();
      info.name = dev.getInfo<CL_DEVICE_NAME>();
      info.version = dev.getInfo<CL_DEVICE_VERSION>();
      info.gpu = (dev.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_GPU) != 0;
      info.images = dev.getInfo<CL_DEVICE_IMAGE_SUPPORT>() == CL_TRUE;
      cl_bool unified = CL_FALSE; // deprecated since OpenCL 2.0, still answered; a CPU device is host memory anyway
      clGetDeviceInfo(dev(), CL_DEVICE_HOST_UNIFIED_MEMORY, sizeof(unified), &unified, nullptr);
      info.host_memory = unified == CL_TRUE || (dev.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
      info.global_memory = dev.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
      info.max_allocation = dev.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
      if (const std::uint64_t cap = memory_cap()) { // the device as if it had less memory
        info.global_memory = std::min(info.global_memory, cap);
        info.max_allocation = std::min(info.max_allocation, cap);
      }
      if (const std::uint64_t left = info.host_memory ? address_space_left() : 0) {
        info.global_memory = std::min(info.global_memory, left);
        info.max_allocation = std::min(info.max_allocation, left);
        info.address_space_limited = true;
      }
      if (info.images) {
        info.image_max_width = dev.getInfo<CL_DEVICE_IMAGE2D_MAX_WIDTH>();
        info.image_max_height = dev.getInfo<CL_DEVICE_IMAGE2D_MAX_HEIGHT>();
      }
      found.push_back({dev, info});
    }
  }
  if (found.empty())
    throw DeviceError(missing("no OpenCL device found on any platform"));
  return found;
}

const Found& choose(const std::vector<Found>& found, const std::string& selector)
{
  const std::string sel = lower(selector);
  if (sel.empty() || sel == "gpu" || sel == "cpu") {
    const bool want_gpu = sel != "cpu";
    for (const Found& f : found)
      if (f.info.gpu == want_gpu)
        return f;
    if (sel.empty())
      return found.front();
    throw DeviceError("no OpenCL " + sel + " device found (see `meshpaint devices`)");
  }
  int p = -1, d = -1;
  char tail = 0;
  if (std::sscanf(sel.c_str(), "%d:%d%c", &p, &d, &tail) == 2) {
    for (const Found& f : found)
      if (f.info.platform_index == p && f.info.device_index == d)
        return f;
    throw DeviceError("no OpenCL device " + selector + " (see `meshpaint devices`)");
  }
  for (const Found& f : found)
    if (lower(f.info.name).find(sel) != std::string::npos ||
        lower(f.info.platform).find(sel) != std::string::npos)
      return f;
  throw DeviceError("no OpenCL device matches '" + selector + "' (see `meshpaint devices`)");
}

} // namespace

std::string DeviceInfo::memory_name() const
{
  return address_space_limited ? "the memory left under the address-space limit (ulimit -v)" : "the device's memory";
}

std::string DeviceInfo::summary() const
{
  char mem[32];
  std::snprintf(mem, sizeof mem, "%.1f GiB", static_cast<double>(global_memory) / (1u << 30));
  return name + " (" + platform + ", " + (gpu ? "GPU" : "CPU") + ", " + mem + ")";
}

Runtime::Runtime(const cl::Device& device, const DeviceInfo& info)
  : device_(device), context_(device), queue_(context_, device_), info_(info)
{
}

void Runtime::set_profiling(bool on)
{
  queue_.finish();
  queue_ = cl::CommandQueue(context_, device_, on ? cl::QueueProperties::Profiling : cl::QueueProperties::None);
}

std::shared_ptr<Runtime> Runtime::open(const std::string& selector)
{
  std::string sel = selector;
  if (sel.empty())
    if (const char* env = std::getenv("MESHPAINT_DEVICE"))
      sel = env;
  const std::vector<Found> found = enumerate();
  const Found& f = choose(found, sel);
  try {
    return std::shared_ptr<Runtime>(new Runtime(f.device, f.info));
  } catch (const cl::Error& e) {
    throw DeviceError("cannot open OpenCL device " + f.info.name + ": " + describe(e));
  }
}

std::vector<DeviceInfo> Runtime::list_devices()
{
  std::vector<DeviceInfo> out;
  for (const Found& f : enumerate())
    out.push_back(f.info);
  return out;
}

} // namespace meshpaint
