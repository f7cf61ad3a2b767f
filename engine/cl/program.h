// Building OpenCL programs from the embedded kernel files.
#pragma once

#include "cl/runtime.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! One kernel source file: its name (for messages) and its text.
struct SourceFile
{
  std::string name;
  std::string text;
};

//! Builds one program from source files, concatenated in order, each
//! preceded by a #line directive so compiler messages name the file.
//! \throw DeviceError carrying the file names and the full build log.
cl::Program build_program(Runtime& runtime, const std::vector<SourceFile>& files, const std::string& options);

//! Rewrites the `<kernel>:LINE:` references of compilers that ignore #line
//! (NVIDIA's name lines of the concatenated source) as `file:line:`.
std::string name_source_lines(const std::string& log, const std::vector<SourceFile>& files);

//! The same from files embedded at build time (kernels/).
cl::Program build_program(Runtime& runtime, const std::vector<std::string>& embedded, const std::string& options);

} // namespace meshpaint
