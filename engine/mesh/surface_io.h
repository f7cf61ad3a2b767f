// Writing surfaces through OpenMesh.
#pragma once

#include "mesh/welded_surface.h"

#include <string> // for std::string

namespace meshpaint {

//! Writes OBJ or PLY (by extension) with vertex normals when the surface has
//! them; atomically.
//! \throw InputError for another extension, IOError when writing fails.
void write_surface(const WeldedSurface& surface, const std::string& path);

} // namespace meshpaint
