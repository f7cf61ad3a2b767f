#include "core/host_memory.h"

#include "core/format.h"

#include <cstdlib> // for std::getenv
#include <fstream> // for std::ifstream
#include <string>  // for std::string

#include <unistd.h> // for sysconf

namespace meshpaint {

std::size_t available_host_memory()
{
  if (const char* text = std::getenv("MESHPAINT_HOST_MEMORY"); text && *text)
    return std::size_t(parse_memory_size("MESHPAINT_HOST_MEMORY", text));
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::size_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:")
      return kib * 1024;
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? std::size_t(pages) * std::size_t(page) : 0;
}

} // namespace meshpaint
