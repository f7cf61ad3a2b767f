// The import steps between a file's polygons and a base mesh: coincident
// vertices welded, faces oriented consistently, closed components outward,
// all through CGAL's polygon-mesh processing.
#pragma once

#include "mesh/polygon_soup.h"

#include <cstddef> // for std::size_t

namespace meshpaint {

//! Counts of what the import steps changed.
struct SoupSteps
{
  std::size_t vertices_welded = 0;          //!< vertices merged into another within the tolerance
  double weld_tolerance = 0;                //!< absolute distance used
  std::size_t degenerate_faces_dropped = 0; //!< fewer than 3 distinct vertices (also after welding)
  std::size_t duplicate_faces_dropped = 0;  //!< the corners of another face, either orientation
  std::size_t faces_flipped = 0;            //!< turned to agree with their neighbours
  std::size_t components_turned_outward = 0;
  std::size_t nonorientable_components = 0; //!< cut open at vertices to orient them
  std::size_t vertices_cut = 0;             //!< vertex copies made for those cuts
  //! The faces were an oriented manifold as given (no edge in more than two
  //! faces, one fan per vertex), so they join as they are.
  bool oriented_manifold = false;
};

//! Relative weld tolerance: a fraction of the bounding-box diagonal.
constexpr double kWeldTolerance = 1e-6;

//! Merges vertices closer than kWeldTolerance times the diagonal (with
//! `weld`), drops degenerate and duplicate faces, orients every connected
//! component consistently and turns closed ones outward. Colours follow
//! their vertices (merged vertices take the mean), and so do labels (merged
//! vertices take the most frequent id, the smallest of a tie).
SoupSteps import_soup(PolygonSoup& soup, bool weld);

} // namespace meshpaint
