// One OpenCL device shared by every test in a process.
#pragma once

#include "atlas/atlas_storage.h"
#include "cl/runtime.h"

#include <memory> // for std::shared_ptr
#include <vector> // for std::vector

namespace meshpaint::test {

//! The default device (MESHPAINT_DEVICE chooses another).
std::shared_ptr<Runtime> runtime();

//! The storages a test runs under: buffers, and images where the device has them.
std::vector<AtlasStorage> storages();

} // namespace meshpaint::test
