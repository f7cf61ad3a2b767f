// meshpaint transfer: a project's channels (and edits) written onto the
// scan's own vertices.

#include "commands.h"
#include "progress_bar.h"

#include "ScanTransfer.h"

#include "core/errors.h"
#include "core/format.h"
#include "project/project_surface.h"

#include <iostream> // for std::cerr
#include <optional> // for std::optional, std::in_place

namespace meshpaint::cli {
namespace {

//! The project read, the scan read, the surface opened, its reference
//! surface, the channels carried over, the file written.
constexpr std::size_t kTransferSteps = 6;

} // namespace

int transfer_command(const Argv& argv)
{
  Args args("transfer", argv, {"--geometry", "--quiet"}, {"--to", "-o", "--device", "--storage"});
  args.expect_positionals(1, 1, "PROJECT --to SCAN -o OUT.{vtp,ply} [--geometry]");
  const std::string path = args.positionals()[0];
  if (!is_project_path(path))
    throw InputError("transfer needs a project (.meshpaint), not '" + path + "'");
  const std::string scan_path = args.value("--to");
  if (scan_path.empty())
    throw InputError("--to SCAN is required");
  const std::string out = args.value("-o");
  if (out.empty())
    throw InputError("-o OUT.{vtp,ply} is required");
  const std::string ext = lower_extension(out);
  if (ext != ".vtp" && ext != ".ply")
    throw InputError("cannot write '" + out + "': unknown format '" + ext + "' (.vtp, .ply)");
  ProgressBar bar("meshpaint transfer", args.flag("--quiet"));
  std::optional<ProgressTask> task(std::in_place, &bar, "transferring onto " + scan_path, kTransferSteps);
  const Project project = load_project(path);
  task->step(1);
  vtkSmartPointer<vtkPolyData> scan = read_scan(scan_path);
  task->step(2);
  if (!project.scan.path.empty()) {
    const ScanReference now = scan_reference(scan_path);
    if (now.bytes != project.scan.bytes || now.crc32 != project.scan.crc32)
      bar.print("meshpaint transfer: warning: " + scan_path + " is not the file the project was fitted to (" +
                project.scan.path + ")");
  }
  auto runtime = open_device(args);
  const AtlasStorage storage = chosen_storage(args, *runtime);
  const PaintedSurface painted = open_project_surface(runtime, project, storage)->painted_surface();
  task->step(3);
  const WeldedSurface reference = reference_surface(runtime, project, storage);
  task->step(4);
  const TransferReport r = transfer_to_scan(painted, reference, scan, args.flag("--geometry"));
  task->step(5);
  write_transferred_scan(scan, out, project.labels);
  task->step(kTransferSteps);
  task.reset();
  if (!args.flag("--quiet")) {
    const double diagonal = project.mesh.diagonal();
    std::cerr << "meshpaint transfer: " << out << ": " << scan->GetNumberOfPoints() << " scan vertices, "
              << scan->GetNumberOfCells() << " cells; distance to the surface RMS " << r.rms_distance << " ("
              << format_fixed(100 * r.rms_distance / diagonal, 4) << "% of the diagonal), max " << r.max_distance
              << " (" << format_fixed(100 * r.max_distance / diagonal, 4) << "%)";
    if (args.flag("--geometry"))
      std::cerr << "; moved up to " << r.max_moved;
    std::cerr << "\n";
  }
  return 0;
}

} // namespace meshpaint::cli
