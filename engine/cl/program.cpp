#include "cl/program.h"

#include "cl/kernel_sources.h"
#include "core/errors.h"

namespace meshpaint {

cl::Program build_program(Runtime& runtime, const std::vector<std::string>& embedded, const std::string& options)
{
  std::vector<SourceFile> files;
  for (const std::string& name : embedded)
    files.push_back({name, kernel_source(name)});
  return build_program(runtime, files, options);
}

cl::Program build_program(Runtime& runtime, const std::vector<SourceFile>& files, const std::string& options)
{
  std::string source, names;
  for (const SourceFile& file : files) {
    source += "#line 1 \"" + file.name + "\"\n" + file.text + "\n";
    names += (names.empty() ? "" : ", ") + file.name;
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
