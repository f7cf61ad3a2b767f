#include "cl/program.h"

#include "cl/kernel_sources.h"
#include "core/errors.h"

#include <algorithm> // for std::count
#include <regex>     // for std::sregex_iterator

namespace meshpaint {
namespace {

//! The program's source: each file after a #line naming it.
std::string concatenate(const std::vector<SourceFile>& files)
{
  std::string source;
  for (const SourceFile& file : files)
    source += "#line 1 \"" + file.name + "\"\n" + file.text + "\n";
  return source;
}

} // namespace

std::string name_source_lines(const std::string& log, const std::vector<SourceFile>& files)
{
  std::vector<int> starts; // the concatenated line at which each file's text begins
  int lines = 0;
  for (const SourceFile& file : files) {
    starts.push_back(lines + 2);
    lines += 2 + int(std::count(file.text.begin(), file.text.end(), '\n'));
  }
  static const std::regex unnamed(R"(<[A-Za-z_ ]+>:([0-9]{1,9}):)");
  std::string out;
  auto from = log.cbegin();
  for (std::sregex_iterator m(log.cbegin(), log.cend(), unnamed), end; m != end; ++m) {
    out.append(from, (*m)[0].first);
    const int line = std::stoi((*m)[1].str());
    std::size_t f = 0;
    while (f + 1 < starts.size() && starts[f + 1] <= line)
      ++f;
    out += line < starts[f] ? (*m)[0].str() : files[f].name + ":" + std::to_string(line - starts[f] + 1) + ":";
    from = (*m)[0].second;
  }
  return out.append(from, log.cend());
}

cl::Program build_program(Runtime& runtime, const std::vector<std::string>& embedded, const std::string& options)
{
  std::vector<SourceFile> files;
  for (const std::string& name : embedded)
    files.push_back({name, kernel_source(name)});
  return build_program(runtime, files, options);
}

cl::Program build_program(Runtime& runtime, const std::vector<SourceFile>& files, const std::string& options)
{
  const std::string source = concatenate(files);
  std::string names;
  for (const SourceFile& file : files)
    names += (names.empty() ? "" : ", ") + file.name;
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
                      describe(e) + ", options '" + options + "'):\n" + name_source_lines(log, files));
  }
  return program;
}

} // namespace meshpaint
