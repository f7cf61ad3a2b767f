// The one registry of kernel programs: which embedded kernels/ files make
// which program, each file after the files it needs, built once per runtime
// and build options (as CLBlast's program cache).
#pragma once

#include "cl/runtime.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! The programs the engine builds: kernel families used together.
enum class KernelProgram
{
  Atlas,   //!< subdivide.cl, limit.cl, select.cl, reduce.cl (AtlasEvaluator)
  Detail,  //!< detail.cl and the subdivide.cl it builds on (Multires)
  Brush,   //!< brush.cl, geometry.cl, lighting.cl (PaintSurface)
  Display, //!< display.cl (PaintSurface's display arrays)
  Copy     //!< copy.cl (the benchmarks' copy-bandwidth probe)
};

//! The files `file` needs, then `file`: what it compiles from on its own.
//! \throw DeviceError for a file the registry does not know.
std::vector<std::string> kernel_file_with_needs(const std::string& file);
//! Every kernel file the registry knows, in a valid build order.
std::vector<std::string> kernel_files();
//! The files of a program in build order, each after the files it needs and
//! each once.
std::vector<std::string> kernel_program_files(KernelProgram program);
//! The program built for the runtime's device with `options` (storage_options()),
//! built on first use and then kept by the runtime.
//! \throw DeviceError carrying the build log when it does not build.
const cl::Program& kernel_program(Runtime& runtime, KernelProgram program, const std::string& options);

} // namespace meshpaint
