// meshpaint: the command line. Each command lives in its own file; this one
// dispatches and turns every error into one line and an exit code:
// 2 for bad input, files, and requests that do not fit the device;
// 3 for device failures (no OpenCL platform, kernel build, OpenCL call).

#include "commands.h"

#include "core/errors.h"

#include <iostream> // for std::cerr, std::cout
#include <map>      // for std::map

namespace {

const char* const kUsage = R"(usage: meshpaint COMMAND [ARGS]

commands:
  demo [MESH] [--level L] [-o DIR]    subdivide a bundled scan, write results, print timings
  info MESH                           counts, genus, boundaries, valences, atlas per level
  subdivide MESH --level L [--limit] -o OUT.{obj,ply,vtp}
                                      the level-L surface (welded quads); --limit: limit
                                      positions and point array Normals
  bench subdivide MESH --level L [--json] [--repeats N]
                                      kernels against OpenSubdiv's CpuEvaluator
  devices                             the OpenCL devices (for --device / MESHPAINT_DEVICE)
  help                                this text

common options: --device SEL (gpu, cpu, P:D or part of a name), --storage buffer|image
)";

} // namespace

int main(int argc, char** argv)
{
  using namespace meshpaint;
  using namespace meshpaint::cli;
  const std::string command = argc > 1 ? argv[1] : "help";
  const Argv rest(argv + std::min(argc, 2), argv + argc);
  static const std::map<std::string, int (*)(const Argv&)> commands = {
    {"info", info_command},   {"subdivide", subdivide_command}, {"bench", bench_command},
    {"demo", demo_command},   {"devices", devices_command}};
  try {
    if (command == "help" || command == "--help" || command == "-h") {
      std::cout << kUsage;
      return 0;
    }
    const auto it = commands.find(command);
    if (it == commands.end())
      throw InputError("unknown command '" + command + "' (see meshpaint help)");
    return it->second(rest);
  } catch (const InputError& e) {
    std::cerr << "meshpaint " << command << ": " << e.what() << "\n";
    return 2;
  } catch (const IOError& e) {
    std::cerr << "meshpaint " << command << ": " << e.what() << "\n";
    return 2;
  } catch (const ResourceError& e) {
    std::cerr << "meshpaint " << command << ": " << e.what() << "\n";
    return 2;
  } catch (const DeviceError& e) {
    std::cerr << "meshpaint " << command << ": " << e.what() << "\n";
    return 3;
  } catch (const cl::Error& e) {
    std::cerr << "meshpaint " << command << ": OpenCL error: " << describe(e) << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "meshpaint " << command << ": out of host memory\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "meshpaint " << command << ": internal error: " << e.what() << "\n";
    return 1;
  }
}
