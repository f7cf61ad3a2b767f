#include "core/atomic_file.h"

#include "core/errors.h"

#include <filesystem> // for std::filesystem
#include <unistd.h>   // for getpid

namespace meshpaint {

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write)
{
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw IOError("cannot write '" + path + "': no directory '" + dir.string() + "'");
  const fs::path tmp = dir / ("." + target.stem().string() + ".tmp-" + std::to_string(getpid()) +
                              target.extension().string());
  try {
    write(tmp.string());
    if (!fs::exists(tmp, ec))
      throw IOError("cannot write '" + path + "'");
    fs::rename(tmp, target, ec);
    if (ec)
      throw IOError("cannot write '" + path + "': " + ec.message());
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

} // namespace meshpaint
