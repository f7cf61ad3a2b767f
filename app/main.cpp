// meshpaint: the command line. Each command lives in its own file; this one
// dispatches (run_command() turns errors into one line and an exit code).
// `meshpaint bench ...` runs the benchmark program beside this one, which the
// product does not carry.

#include "commands.h"
#include "library_messages.h"

#include "core/errors.h"

#include <algorithm> // for std::any_of
#include <cerrno>   // for errno
#include <cstring>  // for std::strerror
#include <iostream> // for std::cout
#include <map>      // for std::map
#include <unistd.h> // for execv, readlink

namespace {

const char* const kUsage = R"(usage: meshpaint COMMAND [ARGS]

commands:
  demo [MESH] [--level L] [-o DIR] [--quiet]
                                      subdivide the bunny scan (or MESH), write its limit
                                      surface as DIR/NAME_levelL_limit.vtp, then paint the
                                      bundled strokes into DIR/painted/; print timings
  info MESH [--level L] [--base-faces N]
                                      counts, genus, boundaries, valences, atlas per level,
                                      the memory a fit at L with N base faces needs
  subdivide MESH --level L [--limit] [--quiet] -o OUT.{obj,ply,vtp}
                                      the level-L surface (welded quads); --limit: limit
                                      positions and point array Normals
  bench subdivide MESH [--level L] [--json] [--repeats N] [--quiet]
                                      kernels against OpenSubdiv's CpuEvaluator (level 3)
  paint MESH --strokes S.json [--level L] [--model-level M] [--lod L] [--two-sided] [--quiet] [-o OUTDIR]
        [--gltf FILE.glb|FILE.gltf] [--save P.meshpaint] [--labels labels.json]
        [--screenshot OUT.png [--camera AZ,EL,ZOOM] [--size WxH] [--subsurface N] [--show CHANNEL]]
                                      apply a stroke script (docs/strokes.md); writes
                                      OUTDIR/surface.vtp with the paint channels, and
                                      model.obj + model.mtl + model.gltf + PNG texture
                                      maps; --gltf: the model as one file; --save: the
                                      project to continue from; --screenshot: a rendered
                                      picture (--show: which channel, --subsurface N:
                                      N passes of subsurface scattering)
  view MESH...|PROJECT [--strokes S.json] [--labels labels.json] [--level L] [--lod L] [-o DIR] [--size WxH]
                                      the painting window (docs/window.md); saves the
                                      recorded strokes and the surface into DIR
  stats MESH [--labels labels.json] [--json|--csv] [--level L]
                                      per-label area, centroid and bounds
  fit SCAN [--base-faces N] [--level L] [--direct] [--passes P] [--report FILE.json] [--quiet] -o PROJECT.meshpaint
                                      a project from a scan: coarse base mesh (decimated),
                                      atlas at level L fitted onto the scan; fit error
                                      (--report: also as JSON)
  transfer PROJECT --to SCAN -o OUT.{vtp,ply} [--geometry] [--quiet]
                                      the scan with the project's channels as point
                                      arrays (label, diffuse, ...); --geometry: moved
                                      as the surface was sculpted or smoothed
  bench paint [--json] [--steps N] [--tool sculpt|paint] [--mesh femur|armadillo] [--phases] [--quiet]
                                      brush step times as the paper's Table 1, and
                                      smoothing against VTK and OpenMesh
  bench view [--steps N] [--studio] [--quiet]
                                      the window's frame times while painting, with and
                                      without level of detail, and pick latency (needs X);
                                      --studio: the studio's own frames
  bench fit [--level L] [--max-triangles N] [--json] [--quiet]
                                      fit's time, peak memory and error on every scan and
                                      against scan size; decimation against VTK and CGAL
  devices                             the OpenCL devices (for --device / MESHPAINT_DEVICE)
  help [COMMAND]                      this text, or one command's (also COMMAND --help, -h)
  --version                           the version of meshpaint

MESH: a mesh file (.obj .off .ply .stl .vtp .vtk) or a project (.meshpaint) for info, subdivide,
  paint, view and stats
demo, info, subdivide, paint, view, stats, fit, transfer and bench: --device SEL (gpu, cpu,
  P:D or part of a name), --storage buffer|image
info, subdivide, paint, view, stats and fit: --no-weld: keep coincident vertices apart
info, paint, view and stats: --import-array NAME:CHANNEL (repeatable): the mesh file's vertex
  array NAME as a channel (diffuse, specular, roughness, displacement, label, mask)
)";

//! The first line of each command's entry in kUsage starts with two spaces
//! and the command; its description lines are indented further.
std::string command_usage(const std::string& command)
{
  const std::string text = kUsage;
  const std::string footer = text.substr(text.find("\nMESH: ") + 1);
  std::string found;
  bool inside = false;
  std::size_t at = text.find("commands:\n") + 10;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end - at);
    at = end + 1;
    const bool entry = line.size() > 2 && line.compare(0, 2, "  ") == 0 && line[2] != ' ';
    if (entry)
      inside = line.compare(2, command.size() + 1, command + " ") == 0;
    if (inside && !line.empty())
      found += (entry ? "usage: meshpaint " + line.substr(2) : line) + "\n";
  }
  if (found.empty())
    throw meshpaint::InputError("unknown command '" + command + "' (see meshpaint help)");
  return found + "\n" + footer + "more: docs/cli.md\n";
}

//! Whether ARGS ask for help (`--help` or `-h` anywhere among them).
bool asks_for_help(const std::vector<std::string>& args)
{
  return std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
}

//! Replaces this process by meshpaint-bench from this program's folder.
int run_benchmarks(char** argv)
{
  using meshpaint::ResourceError;
  std::string self(4096, '\0');
  const ssize_t n = readlink("/proc/self/exe", self.data(), self.size() - 1);
  if (n <= 0)
    throw ResourceError("cannot find this program's folder to run meshpaint-bench: " + std::string(std::strerror(errno)));
  self.resize(std::size_t(n));
  const std::string bench = self.substr(0, self.rfind('/') + 1) + "meshpaint-bench";
  argv[1] = const_cast<char*>("meshpaint-bench");
  execv(bench.c_str(), argv + 1);
  throw ResourceError("cannot run " + bench + " (" + std::strerror(errno) +
                      "): the benchmarks are the separate target meshpaint-bench");
}

} // namespace

int main(int argc, char** argv)
{
  using namespace meshpaint;
  using namespace meshpaint::cli;
  const std::string command = argc > 1 ? argv[1] : "help";
  const Argv rest(argv + std::min(argc, 2), argv + argc);
  static const std::map<std::string, int (*)(const Argv&)> commands = {
    {"info", info_command},   {"subdivide", subdivide_command},
    {"demo", demo_command},   {"devices", devices_command}, {"paint", paint_command},
    {"stats", stats_command}, {"transfer", transfer_command},
    {"fit", fit_command}, {"view", view_command}};
  capture_library_messages();
  return run_command("meshpaint", command, [&] {
    if (command == "--version") {
      if (!rest.empty())
        throw InputError("takes no arguments, not '" + rest.front() + "'");
      std::cout << "meshpaint " << MESHPAINT_VERSION << "\n";
      return 0;
    }
    if (command == "help" && !rest.empty()) {
      std::cout << command_usage(asks_for_help(rest) ? command : rest.front());
      return 0;
    }
    if (command == "help" || command == "--help" || command == "-h") {
      std::cout << kUsage;
      return 0;
    }
    if (command == "bench")
      return run_benchmarks(argv);
    const auto it = commands.find(command);
    if (it == commands.end())
      throw InputError("unknown command '" + command + "' (see meshpaint help)");
    if (asks_for_help(rest)) {
      std::cout << command_usage(command);
      return 0;
    }
    return it->second(rest);
  });
}
