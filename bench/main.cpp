// meshpaint-bench: the benchmark programs, apart from the product binary;
// `meshpaint bench ...` runs this with the same arguments. Each benchmark
// prints a table (or JSON) with its peers measured in the same run.

#include "benchmarks.h"

#include "core/errors.h"

#include <map> // for std::map

namespace meshpaint::cli {
namespace {

int bench(const Argv& argv)
{
  Args args("bench", argv, {"--json", "--phases"}, {"--level", "--repeats", "--steps", "--tool", "--mesh", "--max-triangles", "--device", "--storage"});
  const std::string what = args.positionals().empty() ? "" : args.positionals()[0];
  // One parser for all four; an option of another benchmark is refused.
  const std::map<std::string, std::vector<std::string>> foreign = {
    {"subdivide", {"--phases", "--steps", "--tool", "--mesh", "--max-triangles"}},
    {"paint", {"--level", "--repeats", "--max-triangles"}},
    {"view", {"--json", "--phases", "--level", "--repeats", "--tool", "--mesh", "--max-triangles"}},
    {"fit", {"--phases", "--repeats", "--steps", "--tool", "--mesh"}}};
  if (const auto found = foreign.find(what); found != foreign.end())
    for (const std::string& option : found->second)
      if (args.has(option) || args.flag(option))
        throw InputError(option + " is not an option of 'meshpaint bench " + what + "'");
  if (what == "subdivide")
    return bench_subdivide(args);
  if (what == "paint")
    return bench_paint(args);
  if (what == "view")
    return bench_view(args);
  if (what == "fit")
    return bench_fit(args);
  throw InputError("usage: meshpaint bench subdivide MESH [--level L] [--json] [--repeats N] | "
                   "meshpaint bench paint [--json] [--steps N] [--tool sculpt|paint] [--mesh femur|armadillo] [--phases] | "
                   "meshpaint bench view [--steps N] | "
                   "meshpaint bench fit [--level L] [--max-triangles N] [--json]");
}

} // namespace
} // namespace meshpaint::cli

int main(int argc, char** argv)
{
  using namespace meshpaint::cli;
  const Argv args(argv + std::min(argc, 1), argv + argc);
  // Messages name the command as users type it.
  return run_command("meshpaint", "bench", [&] { return bench(args); });
}
