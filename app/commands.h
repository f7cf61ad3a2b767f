// The `meshpaint` commands, each in its own file, and what one command
// lends another.
#pragma once

#include "command_support.h"

#include "atlas/atlas.h"
#include "cl/runtime.h"
#include "paint/paint_scene.h"
#include "paint/stroke.h"
#include "mesh/base_mesh.h"
#include "mesh/welded_surface.h"
#include "project/project.h"

#include <vtkPolyData.h>     // for vtkPolyData
#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <memory>   // for std::shared_ptr, std::unique_ptr
#include <optional> // for std::optional
#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint::cli {

int info_command(const Argv& argv);
int subdivide_command(const Argv& argv);
int demo_command(const Argv& argv);
int devices_command(const Argv& argv);
int paint_command(const Argv& argv);
int stats_command(const Argv& argv);
int transfer_command(const Argv& argv);
int fit_command(const Argv& argv);
int view_command(const Argv& argv);

//! Paints `script` onto the surface and, unless DIR is empty, writes
//! DIR/surface.vtp (with `labels` as field data) and the textured model
//! (model.obj, model.mtl, model.gltf, PNG maps), printing a table of the strokes.
//! With `lod` between 1 and the painting level (exclusive), also
//! DIR/surface_lodL.vtp: the painted surface at that coarser level.
void paint_job(PaintScene& scene, const StrokeScript& script, int model_level, const std::string& dir, bool quiet,
               int lod = -1, const std::vector<LabelClass>& labels = {});

//! \throw InputError unless the path ends in .obj, .ply or .vtp (any case).
void check_surface_format(const std::string& path);
//! Writes OBJ or PLY through OpenMesh, VTP through VTK; atomically.
void write_any(const WeldedSurface& surface, const std::string& path);

} // namespace meshpaint::cli
