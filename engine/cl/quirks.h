// What the engine knows about particular OpenCL implementations.
#pragma once

namespace meshpaint {

//! Settings that must be in place before the first OpenCL call. PoCL: keep
//! compiled kernels in its cache, and pin its workers where every CPU is
//! the process's; anything the user set wins.
void apply_runtime_quirks();

} // namespace meshpaint
