// Text OFF as Geomview defines it, read strictly: every number checked and
// every problem named by its line.
#pragma once

#include "mesh/polygon_soup.h"

#include <string> // for std::string

namespace meshpaint {

//! Reads a text OFF file: the optional ST, C, N, 4 and n prefixes of the
//! keyword (texture coordinates and normals are skipped, vertex colours
//! kept, 4 divides by the homogeneous coordinate, n gives the dimension, 2
//! or 3), comments (#) and blank lines anywhere, the counts on the keyword's
//! line or the next, the edge count optional, and after each face's indices
//! nothing, a colour-map index, or 3 or 4 colour components (integers 0-255
//! or numbers 0-1). Sizes are checked against the file before anything is
//! reserved.
//! \throw InputError "line N: ..." for a malformed, non-finite or missing
//! number, an index out of range, a count the file does not hold, or a body
//! that does not match its counts.
PolygonSoup read_off_text(const std::string& path);

} // namespace meshpaint
