// meshpaint's decimation against VTK's and CGAL's at one face budget.
#pragma once

#include "mesh/base_mesh.h"
#include "project/scan_fit.h"

#include <cstddef> // for std::size_t
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint::cli {

//! One method's decimation of a scan.
struct DecimationPeer
{
  std::string method;
  std::size_t faces = 0;  //!< triangles reached
  double seconds = 0;     //!< median of the repeats, the method's own call only
  FitError scan_to_mesh;  //!< from every scan vertex to the decimated surface, world units
};

//! The scan decimated to `budget` triangles by meshpaint's decimate(), by
//! vtkQuadricDecimation (plain, then with volume preservation) and by
//! CGAL's edge collapse with Garland-Heckbert plane quadrics, each run
//! `repeats` times.
std::vector<DecimationPeer> decimation_peers(const BaseMesh& scan, std::size_t budget, int repeats);

} // namespace meshpaint::cli
