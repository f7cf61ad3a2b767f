// A coarse base mesh from a dense scan, by OpenMesh's decimater.
#pragma once

#include "mesh/base_mesh.h"

#include <cstddef> // for std::size_t

namespace meshpaint {

//! The default face budget for a scan of `faces` triangles: a fiftieth,
//! from 2,500 up to 20,000. Below 2,500 faces the thin parts and borders of
//! small scans (femur, lion head) fit with worst errors of 1 to 4% of the
//! diagonal; at 2,500 under 0.8%.
std::size_t default_base_faces(std::size_t faces);

//! How the decimation went.
struct Decimation
{
  BaseMesh base;              //!< the decimated mesh
  std::size_t budget = 0;     //!< the face budget asked for
  int stages = 0;             //!< stages run, 1 to 3 (see decimate())
  std::size_t stage_faces[3] = {0, 0, 0}; //!< triangles after each stage run
};

//! `mesh` (polygons fanned into triangles) decimated by edge collapses to
//! at most `target_faces` triangles, OpenMesh's quadric error module
//! ordering the collapses, in up to three stages that each go on from the
//! last where it stopped above the budget:
//! 1. the normal-deviation module forbids collapses that widen the cone of
//!    normals a face stands for beyond 60 degrees, border vertices locked;
//! 2. the normal-flipping module instead forbids only collapses that turn
//!    a face by more than 60 degrees at once (on noisy scans the cones of
//!    stage 1 are wide from the start, so stage 1 stops early there);
//! 3. as stage 2 with border vertices free (they stay on border points:
//!    OpenMesh moves a collapsed vertex onto its neighbour).
//! Stops above the budget only when no allowed collapse is left.
//! \throw InputError when the result is not a valid base mesh.
Decimation decimate(const BaseMesh& mesh, std::size_t target_faces);

} // namespace meshpaint
