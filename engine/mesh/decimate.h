// A coarse base mesh from a dense scan, by OpenMesh's decimater.
#pragma once

#include "mesh/base_mesh.h"

#include <cstddef> // for std::size_t

namespace meshpaint {

//! The default face budget for a scan of `faces` triangles: a fiftieth,
//! from 200 up to 20,000.
std::size_t default_base_faces(std::size_t faces);

//! `mesh` (polygons fanned into triangles) decimated by edge collapses to
//! at most `target_faces` triangles: OpenMesh's quadric error module orders
//! the collapses, its normal-deviation module forbids those that turn a face
//! by more than 60 degrees, and border vertices are locked, so borders keep
//! their vertices. Stops earlier when no allowed collapse is left.
//! \throw InputError when the result is not a valid base mesh.
BaseMesh decimate(const BaseMesh& mesh, std::size_t target_faces);

} // namespace meshpaint
