// A legacy .vtk polydata file walked the way VTK's legacy reader will read
// it, before that reader runs. The reader trusts what the file states: cell
// counts inside a cell list, string lengths in binary data, array counts it
// allocates before reading; it recurses on repeated sections, goes on after
// parts it could not read, and spins on long runs of spaces (fuzz findings).
// The walk accepts the format as VTK's writer and the format's description
// lay it out, checks every count against the bytes that follow and every
// ASCII number whole, and refuses anything else by its line.
#ifndef LegacyPolyDataCheck_h
#define LegacyPolyDataCheck_h

#include <string> // for std::string

namespace meshpaint {

//! The bytes of the legacy polydata file `path` as VTK's reader may then
//! read them: walked word by word with the reader's rules (white space
//! between words, a binary block after the end of its header line), every
//! section once, each count no more than the rest of the file holds, ASCII
//! numbers of their declared type and range, cell lists consistent with
//! their counts and offsets, POINT_DATA and CELL_DATA counts equal to the
//! points and cells read, no binary string arrays; METADATA blocks
//! (component names and array information, which nothing here reads, and
//! whose parser in VTK hangs on damaged ones) are left out of the bytes
//! returned.
//! \throw InputError naming `path` and the line, one line.
std::string checked_legacy_polydata(const std::string& path);

} // namespace meshpaint

#endif
