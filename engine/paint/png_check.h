// A PNG file checked through libpng before any image reader decodes it.
#pragma once

#include <cstdint> // for std::uint64_t
#include <string>  // for std::string

namespace meshpaint {

//! Why a PNG file cannot be used as a pattern or stamp, or "" when it can:
//! libpng reads its header, the pixel count (after palette and transparency
//! expansion, as VTK's PNG reader expands them) is checked against
//! `max_samples` and the image data against what the file's size can hold
//! (deflate packs at most 1032 bytes into one) before any row is decoded;
//! then every row is decoded into one row's buffer and the chunks to IEND
//! are read, so that truncation or a bad CRC in a critical chunk is found
//! before the image is decoded for use.
//! \throw IOError when the file cannot be opened.
std::string png_problem(const std::string& path, std::uint64_t max_samples);

} // namespace meshpaint
