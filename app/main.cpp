// meshpaint: the command line. Each command lives in its own file; this one
// dispatches and turns every error into one line (a kernel build failure adds
// the compiler's log below it) and an exit code:
// 2 for bad input, files, and requests that do not fit the device;
// 3 for device failures (no OpenCL platform, kernel build, OpenCL call).

#include "commands.h"

#include "core/errors.h"

#include <iostream> // for std::cerr, std::cout
#include <map>      // for std::map

namespace {

const char* const kUsage = R"(usage: meshpaint COMMAND [ARGS]

commands:
  demo [MESH] [--level L] [-o DIR]    subdivide the bunny scan (or MESH), write its limit
                                      surface as DIR/NAME_levelL_limit.vtp, then paint the
                                      bundled strokes into DIR/painted/; print timings
  info MESH                           counts, genus, boundaries, valences, atlas per level
  subdivide MESH --level L [--limit] [--quiet] -o OUT.{obj,ply,vtp}
                                      the level-L surface (welded quads); --limit: limit
                                      positions and point array Normals
  bench subdivide MESH [--level L] [--json] [--repeats N]
                                      kernels against OpenSubdiv's CpuEvaluator (level 3)
  paint MESH --strokes S.json [--level L] [--model-level M] [--lod L] [--two-sided] [--quiet] [-o OUTDIR]
        [--save P.meshpaint] [--labels labels.json]
        [--screenshot OUT.png [--camera AZ,EL,ZOOM] [--size WxH]]
                                      apply a stroke script (docs/strokes.md); writes
                                      OUTDIR/surface.vtp with the paint channels, and
                                      model.obj + model.mtl + PNG texture maps; --save:
                                      the project to continue from; --screenshot: a
                                      rendered picture
  view MESH...|PROJECT [--strokes S.json] [--level L] [--lod L] [-o DIR] [--size WxH]
                                      the painting window (docs/window.md); saves the
                                      recorded strokes and the surface into DIR
  stats MESH [--labels labels.json] [--json|--csv] [--level L]
                                      per-label area, centroid and bounds
  fit SCAN [--base-faces N] [--level L] [--direct] [--passes P] [--quiet] -o PROJECT.meshpaint
                                      a project from a scan: coarse base mesh (decimated),
                                      atlas at level L fitted onto the scan; fit error
  transfer PROJECT --to SCAN -o OUT.{vtp,ply} [--geometry] [--quiet]
                                      the scan with the project's channels as point
                                      arrays (label, diffuse, ...); --geometry: moved
                                      as the surface was sculpted or smoothed
  bench paint [--json] [--steps N] [--tool sculpt|paint] [--mesh femur|armadillo] [--phases]
                                      brush step times as the paper's Table 1, and
                                      smoothing against VTK and OpenMesh
  bench view [--steps N]              the window's frame times while painting, with and
                                      without level of detail, and pick latency (needs X)
  devices                             the OpenCL devices (for --device / MESHPAINT_DEVICE)
  help                                this text

MESH: a mesh file (.obj .off .ply .stl) or a project (.meshpaint) for info, subdivide,
paint, view and stats
options of demo, info, subdivide, paint, view, stats and bench: --device SEL (gpu, cpu, P:D
or part of a name), --storage buffer|image
)";

//! 2: the user's input or the device's limits; 3: the device; 1: a defect.
int exit_code(const std::exception& e)
{
  using namespace meshpaint;
  if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const IOError*>(&e) ||
      dynamic_cast<const ResourceError*>(&e) || dynamic_cast<const std::bad_alloc*>(&e))
    return 2;
  if (dynamic_cast<const DeviceError*>(&e) || dynamic_cast<const cl::Error*>(&e))
    return 3;
  return 1;
}

std::string message(const std::exception& e, int code)
{
  if (const auto* cl_error = dynamic_cast<const cl::Error*>(&e))
    return "OpenCL error: " + meshpaint::describe(*cl_error);
  if (dynamic_cast<const std::bad_alloc*>(&e))
    return "out of host memory";
  return code == 1 ? std::string("internal error: ") + e.what() : std::string(e.what());
}

} // namespace

int main(int argc, char** argv)
{
  using namespace meshpaint;
  using namespace meshpaint::cli;
  const std::string command = argc > 1 ? argv[1] : "help";
  const Argv rest(argv + std::min(argc, 2), argv + argc);
  static const std::map<std::string, int (*)(const Argv&)> commands = {
    {"info", info_command},   {"subdivide", subdivide_command}, {"bench", bench_command},
    {"demo", demo_command},   {"devices", devices_command}, {"paint", paint_command},
    {"stats", stats_command}, {"transfer", transfer_command},
    {"fit", fit_command}, {"view", view_command}};
  try {
    if (command == "help" || command == "--help" || command == "-h") {
      std::cout << kUsage;
      return 0;
    }
    const auto it = commands.find(command);
    if (it == commands.end())
      throw InputError("unknown command '" + command + "' (see meshpaint help)");
    return it->second(rest);
  } catch (const std::exception& e) {
    const int code = exit_code(e);
    std::cerr << "meshpaint " << command << ": " << message(e, code) << "\n";
    return code;
  }
}
