#include "fuzz_input_file.h"

#include <cstdio>     // for std::remove
#include <filesystem> // for std::filesystem::temp_directory_path
#include <fstream>    // for std::ofstream
#include <stdexcept>  // for std::runtime_error
#include <unistd.h>   // for getpid

namespace meshpaint::fuzz {

InputFile::InputFile(const std::uint8_t* data, std::size_t size, const std::string& extension)
  : path_((std::filesystem::temp_directory_path() /
           ("meshpaint-fuzz-" + std::to_string(getpid()) + extension)).string())
{
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!out)
    throw std::runtime_error("cannot write " + path_);
}

InputFile::~InputFile() { std::remove(path_.c_str()); }

} // namespace meshpaint::fuzz
