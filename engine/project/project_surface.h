// Between projects and painting surfaces: restoring one from the other.
#pragma once

#include "paint/paint_surface.h"
#include "project/project.h"

#include <memory> // for std::shared_ptr, std::unique_ptr

namespace meshpaint {

//! A painting surface in the project's state: the atlas rebuilt from the
//! base mesh (the same spatial order, so the same patches), the finest
//! positions and channels written back bit for bit, the limit recomputed.
//! \throw InputError when the project's layers do not fit the atlas its mesh
//! makes; ResourceError and DeviceError as PaintSurface.
std::unique_ptr<PaintSurface> open_project_surface(std::shared_ptr<Runtime> runtime, const Project& project,
                                                   AtlasStorage storage);

//! The surface's state as a project, with the given labels, history
//! (a stroke script) and scan.
Project capture_project(PaintSurface& surface, std::vector<LabelClass> labels, std::string history,
                        ScanReference scan = {});

} // namespace meshpaint
