// The host's memory, as the operating system reports it.
#pragma once

#include <cstddef> // for std::size_t

namespace meshpaint {

//! Bytes the host can give a new allocation without swapping: Linux's
//! MemAvailable (free memory plus caches it can drop), else the free
//! physical pages; 0 when neither is known.
std::size_t available_host_memory();

} // namespace meshpaint
