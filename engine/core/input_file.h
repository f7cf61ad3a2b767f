// Reading a whole input file (stroke script, label table) with its kind and
// size checked before anything is read.
#pragma once

#include <cstdint> // for std::uint64_t
#include <string>  // for std::string

namespace meshpaint {

//! Largest stroke script read: a recorded session of 10,000 strokes takes a
//! few megabytes.
constexpr std::uint64_t kMaxStrokeScriptBytes = std::uint64_t(256) << 20;
//! Largest label table read.
constexpr std::uint64_t kMaxLabelTableBytes = std::uint64_t(64) << 20;

//! The bytes of a regular file of at most `max_bytes`. Devices, FIFOs and
//! folders are refused without waiting on them (`/dev/zero`, a pipe nobody
//! writes), so is a file over the limit; `what` names the file's role in
//! messages ("stroke script").
//! \throw IOError when the file is missing or unreadable; InputError when it
//! is not a regular file or is too large.
std::string read_input_file(const std::string& path, std::uint64_t max_bytes, const std::string& what);

} // namespace meshpaint
