// Writing surfaces through OpenMesh.
#pragma once

#include "mesh/openmesh_types.h"
#include "mesh/welded_surface.h"

#include <OpenMesh/Core/IO/Options.hh>                // for OpenMesh::IO::Options
#include <OpenMesh/Core/IO/exporter/BaseExporter.hh> // for OpenMesh::IO::BaseExporter

#include <string> // for std::string

namespace meshpaint {

//! Writes OBJ or PLY (by extension) with vertex normals when the surface has
//! them; atomically.
//! \throw InputError for another extension, IOError when writing fails.
void write_surface(const WeldedSurface& surface, const std::string& path);

//! Writes `mesh` as the format of `path`'s extension through OpenMesh, into
//! memory first, then atomically (write_bytes_atomically()): OpenMesh's
//! writers do not all report a short write to a file.
//! \throw IOError when OpenMesh refuses; StorageError or IOError from the write.
void write_openmesh(const PolyMesh& mesh, const std::string& path, OpenMesh::IO::Options options);

//! The same for any source of points, polygons and properties that
//! OpenMesh's writers can read.
void write_exported(OpenMesh::IO::BaseExporter& exporter, const std::string& path, OpenMesh::IO::Options options);

} // namespace meshpaint
