// A quick look at a mesh file before OpenMesh parses it: what OpenMesh's
// readers would otherwise skip without a word (text coordinates "nan" or
// "inf", faces a reader leaves out), and the malformed structure they would
// abort, loop or exhaust memory on (a face corner without an index, counts
// the file cannot hold, a PLY header without its end).
#pragma once

#include <string> // for std::string

namespace meshpaint {

struct FileCensus
{
  long declared_faces = -1;    //!< faces the file says or shows it has; -1 unknown
  long nonfinite_line = -1;    //!< first text line with a "nan"/"inf" number, 1-based
  std::string nonfinite_token; //!< that number as written
  std::string problem;         //!< malformed structure, e.g. "line 4: ..."; empty: none found
  bool binary = false;         //!< binary PLY, STL or OFF
  bool text = false;           //!< text that may open with a UTF-8 byte-order mark
};

//! Scans OBJ and ASCII PLY/STL text (a UTF-8 byte-order mark skipped), the
//! header of binary PLY and OFF, and binary STL whole (its length must be
//! its triangles', its numbers finite). Text OFF has its own strict reader
//! (read_off_text()). The first structural problem found ends the scan; a
//! file that ends before its header's counts are met is a problem.
FileCensus take_census(const std::string& path, const std::string& lower_extension);

//! The faces a PLY, OFF or binary STL file's header says it has, read from
//! the header alone (no body): a plan before reading. -1 where the format
//! states none (OBJ, ASCII STL) or the header is unreadable or claims more
//! than the file's bytes can hold (the reader then says what is wrong).
long header_face_count(const std::string& path, const std::string& lower_extension);

} // namespace meshpaint
