#include "command_support.h"

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/format.h"  // for meshpaint::lower_extension
#include "mesh/base_mesh.h" // for meshpaint::readable_mesh_extensions
#include "PolyDataFiles.h"
#include "project/imported_channels.h"
#include "project/imported_labels.h"
#include "project/project_surface.h"

#include <algorithm>    // for std::find
#include <filesystem>   // for std::filesystem
#include <iostream>     // for std::cerr
#include <new>          // for std::bad_alloc
#include <system_error> // for std::system_error, std::errc

#ifndef MESHPAINT_SOURCE_DIR
#error "MESHPAINT_SOURCE_DIR must name the source tree"
#endif

namespace meshpaint::cli {
namespace {

//! Whether `e` says the host ran out of memory or threads (std::thread and
//! std::async report a failed pthread_create as a system_error).
bool out_of_host_resources(const std::exception& e)
{
  if (dynamic_cast<const std::bad_alloc*>(&e))
    return true;
  const auto* system = dynamic_cast<const std::system_error*>(&e);
  return system && (system->code() == std::errc::resource_unavailable_try_again ||
                    system->code() == std::errc::not_enough_memory);
}

//! 2: the user's input or the device's limits; 3: the device, the disk or the host's
//! memory; 1: a defect.
int exit_code(const std::exception& e)
{
  using namespace meshpaint;
  if (dynamic_cast<const StorageError*>(&e))
    return 3;
  if (dynamic_cast<const InputError*>(&e) || dynamic_cast<const IOError*>(&e) ||
      dynamic_cast<const ResourceError*>(&e))
    return 2;
  if (dynamic_cast<const DeviceError*>(&e) || dynamic_cast<const cl::Error*>(&e) || out_of_host_resources(e))
    return 3;
  return 1;
}

std::string message(const std::exception& e, int code)
{
  if (const auto* cl_error = dynamic_cast<const cl::Error*>(&e))
    return "OpenCL error: " + meshpaint::describe(*cl_error);
  if (dynamic_cast<const std::bad_alloc*>(&e))
    return "out of host memory";
  if (out_of_host_resources(e))
    return std::string("out of host memory or threads: ") + e.what();
  return code == 1 ? std::string("internal error: ") + e.what() : std::string(e.what());
}


} // namespace

int run_command(const std::string& program, const std::string& command, const std::function<int()>& run)
{
  remove_temporaries_on_signals(); // an interrupted save leaves no temporary behind
  try {
    return run();
  } catch (const std::exception& e) {
    const int code = exit_code(e);
    std::cerr << program << " " << command << ": " << message(e, code) << "\n";
    return code;
  }
}


std::shared_ptr<Runtime> open_device(const Args& args) { return Runtime::open(args.value("--device")); }

ImportOptions import_options(const Args& args)
{
  ImportOptions options;
  options.weld = !args.flag("--no-weld");
  for (const std::string& text : args.values("--import-array"))
    options.arrays.push_back(parse_array_import(text));
  return options;
}

namespace {

//! A mesh file by its extension's reader, through the import steps.
BaseMesh load_any(const std::string& path, const ImportOptions& options)
{
  const auto& exts = readable_mesh_extensions();
  if (!is_polydata_path(path) && std::find(exts.begin(), exts.end(), lower_extension(path)) == exts.end() &&
      std::filesystem::is_regular_file(path))
    throw InputError("cannot read '" + path + "': unknown mesh format '" + lower_extension(path) +
                     "' (readable: .obj .off .ply .stl .vtp .vtk)");
  return is_polydata_path(path) ? load_polydata_mesh(path, options) : load_mesh(path, options);
}

} // namespace

BaseMesh load_reported(const std::string& path, const ImportOptions& options)
{
  BaseMesh mesh = load_any(path, options);
  report_import(path, mesh);
  return mesh;
}

void report_import(const std::string& path, const BaseMesh& mesh)
{
  for (const std::string& line : mesh.report.lines())
    std::cerr << "meshpaint: " << path << ": repaired: " << line << "\n";
  for (const std::string& line : mesh.report.step_lines())
    std::cerr << "meshpaint: " << path << ": imported: " << line << "\n";
}

MeshOrProject open_mesh_or_project(const std::string& path, const ImportOptions& options, bool report)
{
  MeshOrProject input;
  input.path = path;
  if (is_project_path(path)) {
    if (!options.arrays.empty())
      throw InputError("--import-array reads mesh files; '" + path + "' is a project, whose channels are its own");
    input.project = load_project(path);
  }
  else
    input.loaded = report ? load_reported(path, options) : load_any(path, options);
  return input;
}

int input_level(const Args& args, const MeshOrProject& input, int fallback)
{
  if (!input.project)
    return args.integer("--level", fallback, 1, kMaxLevel);
  const int own = input.project->level;
  if (args.has("--level") && args.integer("--level", own, 1, kMaxLevel) != own)
    throw InputError(input.path + " is a level-" + std::to_string(own) + " project; --level " +
                     args.value("--level") + " cannot change that");
  return own;
}

int scene_level(const Args& args, const std::vector<MeshOrProject>& inputs, int fallback)
{
  const MeshOrProject& first = inputs.front();
  const int level = input_level(args, first, fallback);
  for (const MeshOrProject& other : inputs)
    if (input_level(args, other, level) != level)
      throw InputError("'" + other.path + "' is at level " + std::to_string(input_level(args, other, level)) +
                       ", '" + first.path + "' at " + std::to_string(level) + ": a scene paints at one level");
  return level;
}

void check_edit_levels(const StrokeScript& script, int level)
{
  for (std::size_t k = 0; k < script.strokes.size(); ++k)
    if (script.strokes[k].edit_level() > level)
      throw InputError("stroke " + std::to_string(k) + ": \"edit_level\" " +
                       std::to_string(script.strokes[k].edit_level()) + " is finer than the painting level " +
                       std::to_string(level));
}

std::unique_ptr<PaintSurface> open_paint_surface(const std::shared_ptr<Runtime>& runtime, AtlasStorage storage,
                                                 const MeshOrProject& input, int level)
{
  if (input.project)
    return open_project_surface(runtime, *input.project, storage);
  auto surface = std::make_unique<PaintSurface>(runtime, input.loaded, level, storage);
  apply_imported_channels(*surface);
  apply_imported_labels(*surface);
  return surface;
}

void check_output_folder(const std::string& path)
{
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw IOError("cannot write '" + path + "': no directory '" + dir.string() + "'");
}

AtlasStorage chosen_storage(const Args& args, const Runtime& runtime)
{
  return args.has("--storage") ? parse_storage(args.value("--storage")) : default_storage(runtime.info());
}

std::string scans_dir() { return std::string(MESHPAINT_SOURCE_DIR) + "/data/scans"; }

std::string strokes_dir() { return std::string(MESHPAINT_SOURCE_DIR) + "/data/strokes"; }

} // namespace meshpaint::cli
