// A first reduction of very large scans: passes of independent quadric edge
// collapses, linear in the mesh per pass, before the ordered collapse.
#pragma once

#include "mesh/edge_collapse.h"

#include <cstddef> // for std::size_t

namespace meshpaint {

//! How the passes went.
struct QuadricPasses
{
  int passes = 0;          //!< passes run
  std::size_t faces = 0;   //!< triangles after them
};

//! Collapses edges of the triangle mesh `mesh` in passes until it has at
//! most `target_faces` triangles, or until a pass removes under 1% of them.
//! Each pass ranks every edge by its Garland-Heckbert plane quadric cost
//! (faces weighted by area, border edges by planes across them, so borders
//! stay where they are). Of the cheapest quarter, an edge collapses when no
//! edge at its ends is cheaper (edges refused earlier aside) and neither
//! end was kept by a collapse of this pass; the edges go in memory order.
//! The costs stay exact within a pass, and no priority queue is kept. A
//! pass that would overshoot the budget goes in cost order instead. The
//! kept vertex goes to whichever of the two ends or the midpoint costs
//! least. A collapse must keep the mesh a manifold (CGAL's link condition),
//! must not pinch a border, and must not turn any face of its star by more
//! than 60 degrees.
//!
//! Far cheaper per collapse than an ordered collapse on scans of millions
//! of triangles, whose priority queue and its updates miss the cache; less
//! faithful at the last few thousand faces, which the ordered collapse
//! chooses better. decimate() runs these passes first on large scans.
//! \pre `mesh` is a triangle mesh without removed elements.
QuadricPasses reduce_in_passes(CgalMesh& mesh, std::size_t target_faces);

} // namespace meshpaint
