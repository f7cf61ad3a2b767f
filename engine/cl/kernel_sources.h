// The files of kernels/, embedded in the binary at build time.
#pragma once

#include <string> // for std::string

namespace meshpaint {

//! Text of the embedded file `name` (e.g. "subdivide.cl").
//! \throw DeviceError when no such file was embedded.
const std::string& kernel_source(const std::string& name);

} // namespace meshpaint
