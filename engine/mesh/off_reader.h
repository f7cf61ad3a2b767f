// OFF as Geomview defines it, read strictly: every number checked and every
// problem named by its line (text) or face (binary).
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

//! Reads a binary OFF file (first line 'OFF BINARY') laid out as Geomview
//! defines it: 32-bit big-endian counts, vertex floats and face integers,
//! each face's vertex indices followed by a colour count (0, 1, 3 or 4) and
//! that many floats (a colour-map index or RGB[A] 0-1), which become the
//! face colours; also little-endian. Returns false, reading nothing, when
//! the file is laid out as OpenMesh writes it (little-endian, nothing after
//! each face's indices) or its header is not 'OFF BINARY': OpenMesh's
//! reader and the census take those.
//! \throw InputError when the body fits no layout, naming the face or
//! vertex where the closest one fails, or fits more than one (ambiguous).
bool read_off_binary(const std::string& path, PolygonSoup& soup);

} // namespace meshpaint
