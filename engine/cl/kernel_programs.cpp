#include "cl/kernel_programs.h"

#include "cl/program.h"
#include "core/errors.h"

#include <algorithm> // for std::find

namespace meshpaint {
namespace {

//! A kernel file and the files it uses (its direct needs; theirs come first).
struct KernelFile
{
  const char* name;
  std::vector<const char*> needs;
};

// In a valid build order: every file after what it needs.
const std::vector<KernelFile>& registry()
{
  static const std::vector<KernelFile> files = {
    {"atlas_types.h", {}},
    {"atlas_access.cl", {"atlas_types.h"}},
    {"subdivide.cl", {"atlas_access.cl"}},
    {"limit.cl", {"atlas_access.cl"}},
    {"select.cl", {"atlas_types.h"}},
    {"reduce.cl", {"atlas_access.cl"}},
    {"lanes.cl", {"atlas_access.cl"}},
    {"detail.cl", {"subdivide.cl", "lanes.cl"}},
    {"brush_space.cl", {"atlas_access.cl"}},
    {"brush.cl", {"brush_space.cl", "lanes.cl"}},
    {"geometry.cl", {"brush_space.cl", "lanes.cl"}},
    {"lighting.cl", {"atlas_access.cl"}},
    {"display.cl", {"atlas_access.cl"}},
    {"copy.cl", {}},
  };
  return files;
}

std::vector<std::string> program_roots(KernelProgram program)
{
  switch (program) {
  case KernelProgram::Atlas: return {"subdivide.cl", "limit.cl", "select.cl", "reduce.cl"};
  case KernelProgram::Detail: return {"detail.cl"};
  case KernelProgram::Brush: return {"brush.cl", "geometry.cl", "lighting.cl"};
  case KernelProgram::Display: return {"display.cl"};
  case KernelProgram::Copy: return {"copy.cl"};
  }
  return {};
}

const KernelFile& find_file(const std::string& name)
{
  for (const KernelFile& f : registry())
    if (name == f.name)
      return f;
  throw DeviceError("kernel file " + name + " is not in the kernel registry");
}

//! Appends `name` after its needs, skipping files already in `out`.
void add_with_needs(const std::string& name, std::vector<std::string>& out)
{
  if (std::find(out.begin(), out.end(), name) != out.end())
    return;
  for (const char* need : find_file(name).needs)
    add_with_needs(need, out);
  out.push_back(name);
}

} // namespace

std::vector<std::string> kernel_file_with_needs(const std::string& file)
{
  std::vector<std::string> out;
  add_with_needs(file, out);
  return out;
}

std::vector<std::string> kernel_files()
{
  std::vector<std::string> out;
  for (const KernelFile& f : registry())
    out.push_back(f.name);
  return out;
}

std::vector<std::string> kernel_program_files(KernelProgram program)
{
  std::vector<std::string> out;
  for (const std::string& root : program_roots(program))
    add_with_needs(root, out);
  return out;
}

const cl::Program& kernel_program(Runtime& runtime, KernelProgram program, const std::string& options)
{
  auto& cache = runtime.program_cache();
  const auto key = std::make_pair(int(program), options);
  auto it = cache.find(key);
  if (it == cache.end())
    it = cache.emplace(key, build_program(runtime, kernel_program_files(program), options)).first;
  return it->second;
}

} // namespace meshpaint
