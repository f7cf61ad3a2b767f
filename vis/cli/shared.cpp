#include "commands.h"

#include <iostream> // for std::cerr

#ifndef MESHPAINT_SOURCE_DIR
#error "MESHPAINT_SOURCE_DIR must name the source tree"
#endif

namespace meshpaint::cli {

std::shared_ptr<Runtime> open_device(const Args& args) { return Runtime::open(args.value("--device")); }

BaseMesh load_reported(const std::string& path)
{
  BaseMesh mesh = load_mesh(path);
  for (const std::string& line : mesh.report.lines())
    std::cerr << "meshpaint: " << path << ": repaired: " << line << "\n";
  return mesh;
}

std::string scans_dir() { return std::string(MESHPAINT_SOURCE_DIR) + "/data/scans"; }

std::string strokes_dir() { return std::string(MESHPAINT_SOURCE_DIR) + "/data/strokes"; }

} // namespace meshpaint::cli
