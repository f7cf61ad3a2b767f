// meshpaint-bench: the benchmark programs, apart from the product binary;
// `meshpaint bench ...` runs this with the same arguments. Each benchmark
// prints a table (or JSON) with its peers measured in the same run.

#include "benchmarks.h"
#include "library_messages.h"

#include "core/errors.h"

#include <iostream> // for std::cout
#include <map>      // for std::map

namespace meshpaint::cli {
namespace {

const char* const kUsage = R"(usage: meshpaint bench subdivide MESH [--level L] [--json] [--repeats N] [--quiet]
       meshpaint bench paint [--json] [--steps N] [--tool sculpt|paint] [--mesh femur|armadillo] [--phases] [--quiet]
       meshpaint bench view [--steps N] [--studio] [--quiet]
       meshpaint bench fit [--level L] [--max-triangles N] [--json]
       (the same as meshpaint-bench ...)

  subdivide   kernels against OpenSubdiv's CpuEvaluator (level 3)
  paint       brush step times as the paper's Table 1, and smoothing against VTK and OpenMesh
  view        the window's frame times while painting, with and without level of detail,
              and pick latency (needs X); --studio: the studio's own frames, its view
              driven by Qt mouse events
  fit         fit's time, peak memory and error on every scan and against scan size (noisy
              refined femur scans); the decimation against VTK's and CGAL's at fit's budget

options: --device SEL (gpu, cpu, P:D or part of a name), --storage buffer|image;
subdivide, paint and view: --quiet (no progress on stderr)
more: docs/cli.md
)";

int bench(const Argv& argv)
{
  for (const std::string& a : argv)
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    }
  if (argv.size() == 1 && argv[0] == "--version") {
    std::cout << "meshpaint-bench " << MESHPAINT_VERSION << "\n";
    return 0;
  }
  Args args("bench", argv, {"--json", "--phases", "--quiet", "--studio"}, {"--level", "--repeats", "--steps", "--tool", "--mesh", "--max-triangles", "--device", "--storage"});
  const std::string what = args.positionals().empty() ? "" : args.positionals()[0];
  // One parser for all four; an option of another benchmark is refused.
  const std::map<std::string, std::vector<std::string>> foreign = {
    {"subdivide", {"--phases", "--steps", "--tool", "--mesh", "--max-triangles", "--studio"}},
    {"paint", {"--level", "--repeats", "--max-triangles", "--studio"}},
    {"view", {"--json", "--phases", "--level", "--repeats", "--tool", "--mesh", "--max-triangles"}},
    {"fit", {"--phases", "--repeats", "--steps", "--tool", "--mesh", "--studio"}}};
  if (const auto found = foreign.find(what); found != foreign.end())
    for (const std::string& option : found->second)
      if (args.has(option) || args.flag(option))
        throw InputError(option + " is not an option of 'meshpaint bench " + what + "'");
  if (what == "subdivide")
    return bench_subdivide(args);
  if (what == "paint")
    return bench_paint(args);
  if (what == "view")
    return args.flag("--studio") ? bench_view_studio(args) : bench_view(args);
  if (what == "fit")
    return bench_fit(args);
  throw InputError("usage: meshpaint bench subdivide MESH [--level L] [--json] [--repeats N] [--quiet] | "
                   "meshpaint bench paint [--json] [--steps N] [--tool sculpt|paint] [--mesh femur|armadillo] [--phases] [--quiet] | "
                   "meshpaint bench view [--steps N] [--studio] [--quiet] | meshpaint bench fit [--level L] [--max-triangles N] [--json] "
                   "(see meshpaint bench --help)");
}

} // namespace
} // namespace meshpaint::cli

int main(int argc, char** argv)
{
  using namespace meshpaint::cli;
  const Argv args(argv + std::min(argc, 1), argv + argc);
  capture_library_messages();
  // Messages name the command as users type it.
  return run_command("meshpaint", "bench", [&] { return bench(args); });
}
