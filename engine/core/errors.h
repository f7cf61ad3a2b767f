// Exception types of the engine. The command line turns each into a message
// and an exit code (docs/cli.md).
#pragma once

#include <stdexcept> // for std::invalid_argument, std::runtime_error
#include <string>    // for std::string

namespace meshpaint {

//! Bad user input: a mesh, a parameter or a file that cannot be used.
class InputError : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

//! A file that cannot be opened, read or written.
class IOError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

//! The file system failed a write: no space left, quota exceeded, or an I/O
//! error. The file being written is left as it was before.
class StorageError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

//! A request that does not fit the device (memory, image size); the message
//! names the limit and what would fit.
class ResourceError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

//! No usable OpenCL device, a kernel that does not build, or a failed call.
class DeviceError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace meshpaint
