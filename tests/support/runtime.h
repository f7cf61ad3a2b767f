// One OpenCL device shared by every test in a process.
#pragma once

#include "cl/runtime.h"

#include <memory> // for std::shared_ptr

namespace meshpaint::test {

//! The default device (MESHPAINT_DEVICE chooses another).
std::shared_ptr<Runtime> runtime();

} // namespace meshpaint::test
