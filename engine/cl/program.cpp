#include "cl/program.h"

#include "cl/kernel_sources.h"
#include "core/errors.h"

namespace meshpaint {

cl::Program build_program(Runtime& runtime, const std::vector<std::string>& files,
                          const std::string& options)
{
  std::string source, names;
  for (const std::string& file : files) {
    source += "#line 1 \"" + file + "\"\n" + kernel_source(file) + "\n";
    names += (names.empty() ? "" : ", ") + file;
  }
  cl::Program program;
  try {
    program = cl::Program(runtime.context(), source);
    program.build(std::vector<cl::Device>{runtime.device()}, options.c_str());
  } catch (const cl::Error& e) {
    std::string log;
    try {
      log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(runtime.device());
    } catch (const cl::Error&) {
      log = "(no build log)";
    }
    throw DeviceError("kernel build failed for " + names + " on " + runtime.info().name + " (" +
                      describe(e) + ", options '" + options + "'):\n" + log);
  }
  return program;
}

} // namespace meshpaint
