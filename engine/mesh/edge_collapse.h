// The CGAL surface mesh that meshpaint simplifies, and the stop rule its
// edge collapses share (decimate() and the decimation peers of bench fit
// stop at the same face budget).
#pragma once

#include <CGAL/Simple_cartesian.h> // for CGAL::Simple_cartesian
#include <CGAL/Surface_mesh.h>     // for CGAL::Surface_mesh

#include <cstddef> // for std::size_t

namespace meshpaint {

using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

//! Stops the collapses once the mesh has at most `budget` faces.
struct FaceBudget
{
  const CgalMesh* mesh;
  std::size_t budget;
  template <typename Cost, typename Profile>
  bool operator()(const Cost&, const Profile&, std::size_t, std::size_t) const
  {
    return mesh->number_of_faces() <= budget;
  }
};

} // namespace meshpaint
