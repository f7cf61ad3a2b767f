// A coarse base mesh from a dense scan, by CGAL's surface-mesh simplification.
#pragma once

#include "mesh/base_mesh.h"
#include "mesh/quadric_passes.h"

#include <cstddef> // for std::size_t

namespace meshpaint {

//! The default face budget for a scan of `faces` triangles: a fiftieth,
//! from 2,500 up to 20,000. Below 2,500 faces the thin parts and borders of
//! small scans (femur, lion head) fit with worst errors of 1 to 4% of the
//! diagonal; at 2,500 under 0.8%.
std::size_t default_base_faces(std::size_t faces);

//! Scans of more triangles than this are first reduced by
//! reduce_in_passes(), which is linear per pass; below it the ordered
//! collapse alone takes under 20 s on a 2-core host.
constexpr std::size_t kQuadricPassesAbove = 1000000;
//! The passes stop at this many times the face budget, leaving the last
//! collapses, which shape the base mesh most, to the ordered collapse.
constexpr std::size_t kQuadricPassesLeave = 10;

//! How the decimation went.
struct Decimation
{
  BaseMesh base;              //!< the decimated mesh
  QuadricPasses passes;       //!< the first reduction (0 passes when the scan is small)
  std::size_t budget = 0;     //!< the face budget asked for
  int stages = 0;             //!< stages run, 1 or 2 (see decimate())
  std::size_t stage_faces[2] = {0, 0}; //!< triangles after each stage run
};

//! `mesh` as a CGAL surface mesh, its polygons fanned into triangles.
CgalMesh cgal_triangles(const BaseMesh& mesh);

//! `mesh` (polygons fanned into triangles) decimated by edge collapses to
//! at most `target_faces` triangles: on scans of over kQuadricPassesAbove
//! triangles reduce_in_passes() first, down to kQuadricPassesLeave times
//! the budget; then CGAL's Garland-Heckbert plane
//! quadrics ordering the collapses and placing the new vertices (borders
//! weighted, so that they stay on the scan's borders), in up to two stages,
//! the second going on from where the first stopped above the budget:
//! 1. CGAL's bounded-normal-change filter forbids collapses that turn a
//!    face of the star by more than 90 degrees;
//! 2. without the filter.
//! Stops above the budget only when no collapse keeps the mesh a manifold.
//! \throw InputError when the result is not a valid base mesh.
Decimation decimate(const BaseMesh& mesh, std::size_t target_faces);

} // namespace meshpaint
