// Building OpenCL programs from the embedded kernel files.
#pragma once

#include "cl/runtime.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! Builds one program from embedded files, concatenated in order, each
//! preceded by a #line directive so compiler messages name the file.
//! \throw DeviceError carrying the file names and the full build log.
cl::Program build_program(Runtime& runtime, const std::vector<std::string>& files,
                          const std::string& options);

} // namespace meshpaint
