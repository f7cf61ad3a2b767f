// What the command-line programs (`meshpaint` and `meshpaint-bench`) share:
// the device, the inputs, where the bundled data lives, and the one way an
// error becomes a message and an exit code.
#pragma once

#include "args.h"

#include "atlas/atlas.h"
#include "cl/runtime.h"
#include "mesh/base_mesh.h"
#include "paint/paint_surface.h"
#include "paint/stroke.h"
#include "project/project.h"

#include <functional> // for std::function
#include <memory>     // for std::shared_ptr, std::unique_ptr
#include <optional>   // for std::optional
#include <string>     // for std::string
#include <vector>     // for std::vector

namespace meshpaint::cli {

using Argv = std::vector<std::string>;

//! The device named by --device (or MESHPAINT_DEVICE, or the default).
std::shared_ptr<Runtime> open_device(const Args& args);

//! The import options of the flags (--no-weld, --import-array).
//! \throw InputError for an --import-array that is not NAME:CHANNEL.
ImportOptions import_options(const Args& args);

//! Loads a mesh and reports on stderr what import repaired and what its
//! steps did ("meshpaint: PATH: repaired: ...", "... imported: ...").
BaseMesh load_reported(const std::string& path, const ImportOptions& options = {});

//! The report of load_reported() for a mesh loaded without it.
void report_import(const std::string& path, const BaseMesh& mesh);

//! What the commands that take a mesh take: a mesh file, or a project.
struct MeshOrProject
{
  std::string path;
  BaseMesh loaded;                //!< the mesh file's mesh; empty for a project
  std::optional<Project> project; //!< set when `path` named a project
  //! The base mesh either way (a project's in atlas order).
  const BaseMesh& mesh() const { return project ? project->mesh : loaded; }
};
//! Loads PATH as a project when it ends in .meshpaint, else as a mesh
//! (reporting repairs unless `report` is false: report_import() later).
MeshOrProject open_mesh_or_project(const std::string& path, const ImportOptions& options = {}, bool report = true);
//! The level to work at: a project's own level (a differing --level is an
//! error), else --level, else `fallback`.
int input_level(const Args& args, const MeshOrProject& input, int fallback);
//! The one level a scene of several inputs works at (input_level() of the
//! first). \throw InputError when another input is at a different level.
int scene_level(const Args& args, const std::vector<MeshOrProject>& inputs, int fallback);
//! \throw InputError naming the first stroke whose edit_level is finer
//! than `level`, before anything is painted.
void check_edit_levels(const StrokeScript& script, int level);
//! A painting surface at `level`: the project's state, or the fresh mesh
//! with the file's colours as its diffuse channel.
std::unique_ptr<PaintSurface> open_paint_surface(const std::shared_ptr<Runtime>& runtime, AtlasStorage storage,
                                                 const MeshOrProject& input, int level);
//! Checked before long work, so that it does not fail only at the end (as
//! write_atomically() would).
//! \throw IOError when the folder that is to hold `path` does not exist.
void check_output_folder(const std::string& path);

//! --storage when given, else the device's default.
AtlasStorage chosen_storage(const Args& args, const Runtime& runtime);

//! Where the set-up script puts the scans (data/scans in the source tree).
std::string scans_dir();
//! The bundled stroke scripts (data/strokes in the source tree).
std::string strokes_dir();

//! Runs one command: its exceptions become one line on stderr,
//! "PROGRAM COMMAND: message" (a kernel build failure adds the compiler's
//! log), and the exit code: 2 for bad input, files, and requests that do not
//! fit the device; 3 for device failures; 1 for a defect.
int run_command(const std::string& program, const std::string& command, const std::function<int()>& run);

} // namespace meshpaint::cli
