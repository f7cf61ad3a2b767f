// Between projects and painting surfaces: restoring one from the other.
#pragma once

#include "paint/paint_surface.h"
#include "project/project.h"

#include <memory> // for std::shared_ptr, std::unique_ptr
#include <string> // for std::string

namespace meshpaint {

//! A painting surface in the project's state: the atlas rebuilt from the
//! base mesh (the same spatial order, so the same patches), the finest
//! positions and channels written back bit for bit, the limit recomputed.
//! \throw InputError when the project's layers do not fit the atlas its mesh
//! makes; ResourceError and DeviceError as PaintSurface.
std::unique_ptr<PaintSurface> open_project_surface(std::shared_ptr<Runtime> runtime, const Project& project,
                                                   AtlasStorage storage);

//! The limit surface the project started from (its reference positions,
//! else the base mesh's subdivision), welded like PaintSurface's painted
//! surface: same vertices, same quads.
WeldedSurface reference_surface(std::shared_ptr<Runtime> runtime, const Project& project, AtlasStorage storage);

//! The project's reference positions (its fit; not empty) at painting level
//! `level`: refined from the project's level, or reduced below it, as
//! `meshpaint subdivide` refines or reduces a project's surface. What a
//! project changed to another level starts from.
std::vector<Float4> reference_at_level(std::shared_ptr<Runtime> runtime, const Project& project, int level,
                                       AtlasStorage storage);

//! A project's stroke history as a script ("" is an empty one).
//! \throw InputError when it is not a valid stroke script.
StrokeScript stroke_history(const std::string& history);

//! A stroke history (stroke-script JSON, or "" for none) continued by
//! `applied`, as stroke-script JSON at `level`.
//! \throw InputError when `previous` is not a valid stroke script.
std::string continued_history(const std::string& previous, const std::vector<Stroke>& applied, int level);

//! Fills the project's mesh, level, positions and channels from the
//! surface; labels, history, reference and scan stay as they are.
void capture_surface(PaintSurface& surface, Project& project);

//! Whether save_painted_project() takes the file's lock itself or runs
//! inside a FileLock its caller holds (from reading the project to saving it).
enum class SaveTurn
{
  take,
  held
};

//! Writes a painted surface as a project, atomically: `base` (what a loaded
//! project carries on: labels, reference, scan and stroke history; an empty
//! Project for a fresh surface) with the surface's strokes appended to its
//! history and the surface's mesh, level and layers captured. The one way
//! the command line, vtkPaintSurface and vtkPaintView save projects: with
//! the exclusive FileLock on `path` (runs saving one project take turns),
//! and, where `base.origin` names the same file, only if no other run has
//! saved there since (its strokes would be lost). Returns the origin a next
//! save of this surface to `path` passes in `base.origin`.
//! \throw InputError when `base.history` is not a valid stroke script or
//! another run saved `path` since it was loaded or saved from here; IOError
//! when the file cannot be locked or written.
ProjectOrigin save_painted_project(PaintSurface& surface, Project base, const std::string& path,
                                   SaveTurn turn = SaveTurn::take);

} // namespace meshpaint
