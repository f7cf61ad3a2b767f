// A fuzzer input written to a file, for the loaders that take a path.
#pragma once

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t
#include <string>  // for std::string

namespace meshpaint::fuzz {

//! A file in the temporary folder holding the input, removed on destruction.
//! The name is per process, so parallel fuzzing jobs do not collide.
class InputFile
{
public:
  //! \throw std::runtime_error when the file cannot be written (not a finding).
  InputFile(const std::uint8_t* data, std::size_t size, const std::string& extension);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }

private:
  std::string path_;
};

} // namespace meshpaint::fuzz
