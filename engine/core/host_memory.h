// The host's memory, as the operating system reports it.
#pragma once

#include <cstddef> // for std::size_t

namespace meshpaint {

//! Bytes the host can give a new allocation without swapping: Linux's
//! MemAvailable (free memory plus caches it can drop), else the free
//! physical pages; 0 when neither is known. MESHPAINT_HOST_MEMORY (bytes,
//! or a number with K, M or G), when set, stands for it: a plan for a
//! smaller machine.
//! \throw InputError when MESHPAINT_HOST_MEMORY is set but not such a size.
std::size_t available_host_memory();

} // namespace meshpaint
