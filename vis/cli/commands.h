// The `meshpaint` commands and what they share.
#pragma once

#include "args.h"

#include "atlas/atlas.h"
#include "cl/runtime.h"
#include "paint/stroke.h"
#include "mesh/base_mesh.h"
#include "mesh/welded_surface.h"

#include <memory> // for std::shared_ptr
#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint::cli {

using Argv = std::vector<std::string>;

int info_command(const Argv& argv);
int subdivide_command(const Argv& argv);
int bench_command(const Argv& argv);
int demo_command(const Argv& argv);
int devices_command(const Argv& argv);
int paint_command(const Argv& argv);

//! The device named by --device (or MESHPAINT_DEVICE, or the default).
std::shared_ptr<Runtime> open_device(const Args& args);

//! Loads a mesh and reports on stderr what import repaired.
BaseMesh load_reported(const std::string& path);

//! Where the set-up script puts the scans (data/scans in the source tree).
std::string scans_dir();
//! The bundled stroke scripts (data/strokes in the source tree).
std::string strokes_dir();

//! Paints `script` onto `mesh` and writes DIR/surface.vtp and the textured
//! model (model.obj, model.mtl, PNG maps), printing a table of the strokes.
void paint_job(const std::shared_ptr<Runtime>& runtime, AtlasStorage storage, const BaseMesh& mesh,
               const StrokeScript& script, int level, int model_level, const std::string& dir, bool quiet,
               int lod = -1);

//! \throw InputError unless the path ends in .obj, .ply or .vtp (any case).
void check_surface_format(const std::string& path);
//! Writes OBJ or PLY through OpenMesh, VTP through VTK; atomically.
void write_any(const WeldedSurface& surface, const std::string& path);

} // namespace meshpaint::cli
