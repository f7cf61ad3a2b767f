// The arrays of a .vtp (VTK XML PolyData) file checked against each other
// and against the file's bytes before VTK's XML reader reads it: that reader
// allocates what a damaged header or a damaged last cell offset states
// (10^19 bytes, a fuzz finding) before it finds the data missing.
#ifndef XmlPolyDataCheck_h
#define XmlPolyDataCheck_h

#include <string> // for std::string

namespace meshpaint {

//! For every array VTK's XML polydata reader would read (points, point and
//! cell data, field data, the offsets and connectivity of verts, lines,
//! strips and polys), ascii, binary or appended (raw or base64), with or
//! without compression (zlib, LZ4, LZMA) and with 32- or 64-bit headers:
//! the values it must hold (the piece's NumberOfPoints, NumberOfPolys, ...
//! times NumberOfComponents; NumberOfTuples; the last cell offset for the
//! connectivity) must be what its binary header states and what the file's
//! bytes hold; uncompressed sizes are bounded by `budget_bytes` (the size
//! census's budget for the file) and each compressed block by what its
//! compressor can pack into its bytes.
//! XML the parser cannot read is left to VTK's reader, which says why.
//! VTK's messages meanwhile go to the output window: the caller keeps them.
//! \throw InputError naming `path` and the array, one line.
void check_xml_polydata_arrays(const std::string& path, double budget_bytes);

} // namespace meshpaint

#endif
